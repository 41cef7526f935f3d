// Open boundaries (issue 40; solvers/sources/inflow_profile.h, outflow_buffer.h): an inlet that
// imposes a velocity profile, and an outlet whose outflow buffer holds the flow's speed, so a
// channel runs at its level up to the outlet instead of draining into it; and particle reuse, a
// sink that gives an emitter back room under its max_particles.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "framework/core/state_stream.h"
#include "framework/run/probes.h"
#include "solvers/sources/emitter.h"
#include "tests/physics/scene_helpers.h"
#include "tests/physics/validation_record.h"

namespace upf::testing {
namespace {

constexpr double kSpacing = 0.02;

// A flat channel 1.6 m long and 0.1 m wide: an inlet 0.1 x 0.1 m at 0.5 m/s at its upstream end
// (Q = 5 litres/s) and an outlet (a sink from x = 1.3 m) on the same floor: no overfall.
nlohmann::json flat_channel(const nlohmann::json& outflow) {
  nlohmann::json doc = {
      {"name", "flat_channel"},
      {"particle_spacing", kSpacing},
      {"materials",
       {{"water", {{"type", "liquid"}, {"density", 1000}, {"viscosity", 0.001}}},
        {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {1.6, 0.3, 0.1}}}}},
      {"emitters",
       {{{"material", "water"},
         {"shape", "rectangle"},
         {"size", {0.1, 0.1}},
         {"width_axis", {0, 0, 1}},
         {"center", {0.03, 0.07, 0.05}},
         {"direction", {1, 0, 0}},
         {"speed", 0.5},
         {"nozzle", false}}}},
      {"sinks", {{{"name", "outlet"}, {"min", {1.3, -1, -1}}, {"max", {2, 2, 2}}}}},
      {"time", {{"end", 7.0}, {"dt_max", 0.002}}},
  };
  if (!outflow.is_null()) doc["sinks"][0]["outflow"] = outflow;
  return doc;
}

struct ChannelLevels {
  std::vector<double> depth;  // at each gauge, the mean over 4-7 s
  double in = 0, out = 0;     // particles in and out over 4-7 s
};

// The depths that wave gauges (the "volume" height probe, 3 spacings wide) read along the
// channel's centre line, averaged over 4-7 s, once the flow has settled.
ChannelLevels run_channel(const nlohmann::json& doc, const std::vector<double>& gauges) {
  TestWorld t(doc, 2);
  ProbeDesc gauge;
  gauge.kind = ProbeKind::Height;
  gauge.axis = 1;
  gauge.method = ProbeMethod::Volume;
  gauge.radius = 3 * kSpacing;
  ChannelLevels r;
  r.depth.assign(gauges.size(), 0.0);
  int samples = 0;
  while (t.world->time() < 7.0 - 1e-12) {
    t.world->step(t.world->next_time_step_until(7.0));
    if (t.world->time() < 4.0) continue;
    r.in += double(t.world->last_step().sources.added);
    r.out += double(t.world->last_step().sources.removed);
    if (t.world->step_count() % 10 != 0) continue;
    for (std::size_t g = 0; g < gauges.size(); ++g) {
      gauge.at = Eigen::Vector2d(gauges[g], 0.05);
      r.depth[g] += evaluate_probe(gauge, t.world->particles(), Real(kSpacing));
    }
    ++samples;
  }
  for (double& d : r.depth) d /= double(samples);
  return r;
}

// Reference: uniform flow in a horizontal channel (continuity, Q = W d V, with a hydrostatic
// outlet, as the outflow buffer of Tafuni et al. 2018 gives): the level 5 cm before the outlet
// and in the buffer is the level mid-channel, within 3 %. A bare sink is a free surface at the
// outlet: the liquid accelerates into it and the level there dips (measured 12.6 %), which the
// same gauges must see (over 6 %), so the test tells the two apart.
TEST(OpenBoundaries, AnOutflowBufferHoldsTheChannelsLevelUpToTheOutlet) {
  const std::vector<double> gauges = {0.7, 1.25};  // mid-channel; 5 cm before the outlet
  const ChannelLevels bare = run_channel(flat_channel(nullptr), gauges);
  const ChannelLevels held =
      run_channel(flat_channel({{"direction", {1, 0, 0}}, {"buffer", 4}}), gauges);
  const double bare_dip = 1 - bare.depth[1] / bare.depth[0];
  const double held_dip = 1 - held.depth[1] / held.depth[0];
  record_validation("flat channel, level 5 cm before the outlet / mid-channel, outflow buffer",
                    "uniform channel flow (continuity), hydrostatic outlet", "1", "within 3 %",
                    held.depth[1] / held.depth[0]);
  record_validation("flat channel, the same with a bare sink (the dip the buffer removes)",
                    "free surface at the outlet", "-", "dips over 6 %",
                    bare.depth[1] / bare.depth[0]);
  record_validation("flat channel with outflow buffer: outlet rate / inlet rate, 4-7 s",
                    "mass conservation in steady flow", "1", "within 2 %", held.out / held.in);
  EXPECT_GT(held.depth[0], 0.04) << "the channel carries water";
  EXPECT_LT(std::abs(held_dip), 0.03);
  EXPECT_GT(bare_dip, 0.06);
  EXPECT_NEAR(held.out / held.in, 1.0, 0.02);
}

// Reference: continuity through an outlet of imposed speed, Q = W d V_out: the outlet sets the
// depth of the flow leaving through it, d = Q / (W V_out) = 6.25 cm for 5 litres/s through a
// 0.1 m channel at 0.8 m/s (within 5 %, read in the buffer and just before it), and the channel
// settles to pass what the inlet gives.
TEST(OpenBoundaries, AnImposedOutflowSpeedSetsTheDepthByContinuity) {
  const ChannelLevels r = run_channel(
      flat_channel({{"direction", {1, 0, 0}}, {"buffer", 4}, {"velocity", 0.8}}), {1.2, 1.25});
  const double expected = 0.1 * 0.1 * 0.5 / (0.1 * 0.8);
  const double depth = 0.5 * (r.depth[0] + r.depth[1]);
  record_validation("outlet of imposed speed 0.8 m/s: depth at the outlet",
                    "continuity, d = Q / (W V_out)", "0.0625 m", "within 5 %", depth, "m");
  EXPECT_NEAR(depth, expected, 0.05 * expected);
  EXPECT_NEAR(r.out / r.in, 1.0, 0.02);
}

// Reference: Hagen-Poiseuille flow at a pipe's end, u(r) = 2 U (1 - r^2 / R^2) with U the mean
// speed (White, Fluid Mechanics, 6.4): a parabolic inlet's liquid in its buffer moves at the
// profile fitted through the origin with a centre speed of 2 U within 3 %, and the inlet still
// passes Q = A U (the emitted volume within one layer of A U t).
TEST(OpenBoundaries, AParabolicInletImposesHagenPoiseuillesProfileAtTheRateAU) {
  const double radius = 0.1, mean_speed = 0.5, end = 0.3;
  const nlohmann::json doc = {
      {"name", "pipe_inlet"},
      {"particle_spacing", kSpacing},
      {"gravity", {0, 0, 0}},
      {"materials",
       {{"water", {{"type", "liquid"}, {"density", 1000}, {"viscosity", 0.001}}},
        {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.6, 0.4, 0.4}}}}},
      {"emitters",
       {{{"material", "water"},
         {"radius", radius},
         {"center", {0.05, 0.2, 0.2}},
         {"direction", {1, 0, 0}},
         {"speed", mean_speed},
         {"profile", "parabolic"}}}},
      {"time", {{"end", end}}},
  };
  TestWorld t(doc, 2);
  t.run_until(end);
  const Particles& p = t.world->particles();
  std::size_t emitted = 0;
  double fu = 0, ff = 0;  // least squares of u against f = 1 - r^2 / R^2
  std::size_t columns = 0;
  const double h = kSpacing;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j)
      if (double(i * i + j * j) * h * h <= radius * radius * (1 + 1e-12)) ++columns;
  const double area_radius = h * std::sqrt(double(columns) / 3.14159265358979323846);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    ++emitted;
    const double x = double(p.position[i].x);
    if (x < 0.05 - 0.5 * h || x > 0.05 + 2 * h) continue;  // the inlet's buffer
    const double dy = double(p.position[i].y) - 0.2, dz = double(p.position[i].z) - 0.2;
    const double f = 1 - (dy * dy + dz * dz) / (area_radius * area_radius);
    fu += f * double(p.velocity[i].x);
    ff += f * f;
  }
  const double centre = fu / ff;
  const double area = double(columns) * h * h;
  const double volume = double(emitted) * h * h * h;
  record_validation("parabolic inlet: centre speed / mean speed (fit in the buffer)",
                    "Hagen-Poiseuille, u_max = 2 U", "2", "within 3 %", centre / mean_speed);
  record_validation("parabolic inlet: emitted volume / (A U t)", "continuity, Q = A U", "1",
                    "within one layer", volume / (area * mean_speed * end));
  EXPECT_NEAR(centre / mean_speed, 2.0, 0.06);
  EXPECT_NEAR(volume, area * mean_speed * end, area * h);
}

// Reference: particle reuse as SPlisHSPlasH's emitters do it (a fixed budget of particles that
// leave and come back), with conservation of the count: a hose with max_particles 500 and
// at_limit "reuse" pours into a tank whose floor is half drain, and the drain gives back what it
// takes. At every step the liquid present is exactly what the hose made less what the drain gave
// back, and never more than 500; the hose pours on past 500 as the drain frees room (new ids,
// which never repeat); and a checkpoint taken mid-way resumes to the same bits.
TEST(Emitters, ReuseKeepsAnEmittersParticlesWithinMaxParticlesAndPoursOn) {
  const nlohmann::json doc = {
      {"name", "reuse"},
      {"particle_spacing", kSpacing},
      {"materials",
       {{"water", {{"type", "liquid"}, {"density", 1000}, {"viscosity", 0.001}}},
        {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.2, 0.5, 0.2}}}}},
      {"emitters",
       {{{"name", "hose"},
         {"material", "water"},
         {"shape", "rectangle"},
         {"size", {0.1, 0.1}},
         {"center", {0.1, 0.4, 0.1}},
         {"direction", {0, -1, 0}},
         {"speed", 1.5},
         {"max_particles", 500},
         {"at_limit", "reuse"}}}},
      {"sinks", {{{"min", {0, -1, 0}}, {"max", {0.1, 0.05, 0.2}}, {"reuse", "hose"}}}},
      {"time", {{"end", 1.2}}},
  };
  TestWorld t(doc, 2);
  const auto& hose = dynamic_cast<const Emitter&>(*t.world->sources().front());
  std::size_t most = 0;
  StateWriter saved;
  while (t.world->time() < 1.2 - 1e-12) {
    t.world->step(t.world->next_time_step_until(1.2));
    const std::size_t liquid = t.world->count(ParticleType::Liquid);
    ASSERT_EQ(liquid, hose.created() - hose.returned()) << "t = " << t.world->time();
    most = std::max(most, liquid);
    if (saved.bytes().empty() && t.world->time() >= 0.6) t.world->save_state(saved);
  }
  record_validation("reuse: most liquid particles present, max_particles 500",
                    "SPlisHSPlasH's particle reuse (a fixed budget)", "500", "at most 500",
                    double(most));
  EXPECT_LE(most, 500u);
  EXPECT_GE(most, 450u) << "the budget filled";
  EXPECT_GT(hose.created(), 800u) << "the hose poured on with the room the drain gave back";
  EXPECT_EQ(t.world->particles().id_bound() - hose.created(),
            t.world->particles().size() - t.world->count(ParticleType::Liquid))
      << "every particle the hose made took a new id";
  TestWorld resumed(doc, 2);
  StateReader in(saved.bytes(), "mid-reuse");
  resumed.world->restore_state(in);
  resumed.run_until(1.2);
  ASSERT_EQ(resumed.world->particles().size(), t.world->particles().size());
  EXPECT_EQ(bitwise_differences(state_by_id(t.world->particles()),
                                state_by_id(resumed.world->particles())),
            0u);
}

}  // namespace
}  // namespace upf::testing
