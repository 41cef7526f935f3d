// Plane Poiseuille flow (e.g. Batchelor, An Introduction to Fluid Dynamics, section 4.2): a
// liquid between two fixed no-slip walls a gap H apart, driven by a body force g along the walls,
// reaches u(y) = g y (H - y) / (2 nu). The channel repeats along x and z (a periodic domain,
// framework/world/periodic_box.h), so the flow has no ends: it tests the images across the faces
// as much as the viscosity. The viscosity is implicit (Weiler et al. 2018) at nu = 1 m^2/s, with a
// step far beyond the explicit viscosity's limit 0.070 s^2 / nu (docs/viscosity.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "framework/core/errors.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kSpacing = 0.01;  // m
constexpr double kGap = 0.2;       // m, H: 20 spacings between the walls' faces
constexpr double kPeriod = 0.06;   // m, along x and z: 6 spacings
constexpr double kNu = 1;          // m^2/s
constexpr double kForce = 10;      // m/s^2, g along x: u_max = g H^2 / (8 nu) = 5 cm/s
constexpr double kExplicitLimit = 0.070 * kSpacing * kSpacing / kNu;  // s

nlohmann::json channel_scene(double dt, const std::string& solver) {
  const nlohmann::json liquid = {{"type", "liquid"},
                                 {"density", 1000},
                                 {"viscosity", kNu},
                                 {"boundary_viscosity", kNu},
                                 {"implicit_viscosity", 1},
                                 {"viscosity_tolerance", 1e-6},
                                 {"viscosity_max_iterations", 1000},
                                 {"solver", solver}};
  return {{"name", "poiseuille"},
          {"gravity", {kForce, 0, 0}},
          {"particle_spacing", kSpacing},
          {"materials", {{"liquid", liquid}, {"walls", {{"type", "frozen"}}}}},
          {"periodic", {{"x", {0, kPeriod}}, {"z", {0, kPeriod}}}},
          {"containers",
           {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {kPeriod, kGap, kPeriod}}}}},
          {"fluid_blocks",
           {{{"material", "liquid"}, {"min", {0, 0, 0}}, {"max", {kPeriod, kGap, kPeriod}}}}},
          {"time", {{"fixed_dt", dt}}}};
}

double analytic(double y) {
  return kForce * y * (kGap - y) / (2 * kNu);
}

struct Profile {
  double worst = 0;   // the largest |u - u_analytic| over the layers, / u_max
  double centre = 0;  // the mean u of the two middle layers / the analytic value there
  double spread = 0;  // the largest |u_i - mean of its layer| / u_max: a flow without ends
};

// u_x averaged over each lattice layer y = (j + 1/2) s, against the analytic profile.
Profile measure(const Particles& p) {
  const int layers = int(std::lround(kGap / kSpacing));
  std::vector<double> sum(std::size_t(layers), 0), count(std::size_t(layers), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const int j = std::clamp(int(std::floor(double(p.position[i].y) / kSpacing)), 0, layers - 1);
    sum[std::size_t(j)] += double(p.velocity[i].x);
    count[std::size_t(j)] += 1;
  }
  const double u_max = analytic(kGap / 2);
  Profile out;
  for (int j = 0; j < layers; ++j) {
    const double u = sum[std::size_t(j)] / count[std::size_t(j)];
    out.worst = std::max(out.worst, std::abs(u - analytic((j + 0.5) * kSpacing)) / u_max);
  }
  const std::size_t a = std::size_t(layers / 2 - 1), b = a + 1;
  out.centre = (sum[a] / count[a] + sum[b] / count[b]) /
               (analytic((double(a) + 0.5) * kSpacing) + analytic((double(b) + 0.5) * kSpacing));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const int j = std::clamp(int(std::floor(double(p.position[i].y) / kSpacing)), 0, layers - 1);
    const double mean = sum[std::size_t(j)] / count[std::size_t(j)];
    out.spread = std::max(out.spread, std::abs(double(p.velocity[i].x) - mean) / u_max);
  }
  return out;
}

// Steady state: the slowest mode decays as exp(-pi^2 nu t / H^2), 247 /s; by 0.08 s it is gone.
Profile steady_profile(double dt, const std::string& solver) {
  TestWorld t(channel_scene(dt, solver), 2);
  t.run_until(0.08);
  return measure(t.world->particles());
}

TEST(PoiseuilleFlow, ImplicitViscosityAtNuOneGivesTheParabolicProfileInAPeriodicChannel) {
  const double dt = 1e-3;
  const Profile p = steady_profile(dt, "pcisph");
  std::printf(
      "Poiseuille, nu %g m^2/s, dt %g s (%.0f x the explicit limit): largest layer error %.2f %% "
      "of u_max, centre %.4f of analytic, spread within layers %.2g %%\n",
      kNu, dt, dt / kExplicitLimit, 100 * p.worst, p.centre, 100 * p.spread);
  record_validation(
      "plane Poiseuille flow at nu = 1 m^2/s, implicit viscosity at 143 x the explicit step, "
      "periodic in x and z: largest layer error / u_max",
      "g y (H - y) / (2 nu)", "0", "within 3 %", p.worst);
  EXPECT_LT(p.worst, 0.03);
  EXPECT_NEAR(p.centre, 1, 0.03);
  // Periodic images carry the flow across the faces: no layer varies along x or z.
  EXPECT_LT(p.spread, 0.01);
}

// Every fluid solver shares the viscosity and the periodic domain.
TEST(PoiseuilleFlow, EveryFluidSolverReachesTheProfile) {
  for (const char* solver : {"dfsph", "iisph", "wcsph"}) {
    const Profile p = steady_profile(1e-3, solver);
    std::printf("Poiseuille with %s: largest layer error %.2f %% of u_max, centre %.4f\n", solver,
                100 * p.worst, p.centre);
    EXPECT_LT(p.worst, 0.03) << solver;
  }
}

// Free-slip walls (a boundary material's free_slip; Adami, Hu & Adams 2012, section 2.3): the
// walls take no shear, so the same channel, driven by the same g, has no force against the flow
// and accelerates as a plug, u = g t in every layer (the momentum balance along x of a liquid
// between frictionless walls), with the viscosity and the wall viscosity on (explicit, nu = 0.01:
// free slip refuses the implicit solve). Against no-slip walls the same run's mean is 0.79 g t,
// and the layer on the wall moves at 0.20 g t.
TEST(PoiseuilleFlow, FreeSlipWallsLetTheChannelAccelerateAsAPlug) {
  const double t_end = 0.1, dt = 5e-4;
  nlohmann::json doc = channel_scene(dt, "pcisph");
  auto& liquid = doc["materials"]["liquid"];
  liquid["implicit_viscosity"] = 0;
  liquid["viscosity"] = 0.01;
  liquid["boundary_viscosity"] = 0.01;
  doc["materials"]["walls"]["free_slip"] = 1;
  TestWorld t(doc, 2);
  t.run_until(t_end);
  const Particles& p = t.world->particles();
  const int layers = int(std::lround(kGap / kSpacing));
  std::vector<double> sum(std::size_t(layers), 0), count(std::size_t(layers), 0);
  double total = 0, n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const int j = std::clamp(int(std::floor(double(p.position[i].y) / kSpacing)), 0, layers - 1);
    sum[std::size_t(j)] += double(p.velocity[i].x);
    count[std::size_t(j)] += 1;
    total += double(p.velocity[i].x);
    n += 1;
  }
  const double plug = kForce * t_end;
  const double mean = total / n / plug;
  const double wall_layer = sum[0] / count[0] / plug;
  const std::size_t middle = std::size_t(layers / 2);
  const double centre = sum[middle] / count[middle] / plug;
  std::printf("free-slip channel at %g s: mean u / g t %.4f, wall layer %.4f, centre %.4f\n", t_end,
              mean, wall_layer, centre);
  record_validation("periodic channel between free-slip walls: mean velocity / g t",
                    "momentum balance without wall shear (Adami et al. 2012 free slip)", "1",
                    "within 1 %", mean);
  EXPECT_NEAR(mean, 1, 0.01);
  EXPECT_NEAR(wall_layer, 1, 0.02) << "the layer on the wall keeps up with the plug";
  EXPECT_NEAR(centre, 1, 0.02);
}

// The implicit solve would hold the walls' slip velocity at the step's start: refused, naming
// the free-slip material.
TEST(PoiseuilleFlow, FreeSlipWallsRefuseAnImplicitWallViscosity) {
  nlohmann::json doc = channel_scene(1e-3, "pcisph");
  doc["materials"]["walls"]["free_slip"] = 1;
  try {
    TestWorld t(doc, 1);
    ADD_FAILURE() << "a free-slip wall beside implicit wall viscosity was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/materials/walls/free_slip"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace upf::testing
