// The dam break of samples/dam_break.json (a 0.6 x 0.8 x 0.4 m water column collapsing in a
// 1.6 x 1.0 x 0.4 m tank), run with any fluid solver and checked the same way: mass conserved
// (particle count constant), nothing NaN, no particle out of the tank.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "scene_helpers.h"

namespace upf::testing {

struct DamBreakResult {
  std::size_t liquid_at_start = 0, liquid_at_end = 0;
  std::uint64_t steps = 0;
  double mean_iterations = 0;  // pressure iterations per step
  double max_avg_density_error = 0;
  double front_at_end = 0;  // m: largest x of the liquid
  bool all_finite = true;
  bool all_inside = true;
  Vec3 first_outside{};  // position of the first particle found outside, for the message
};

// The sample at 4 cm spacing (3,000 liquid particles: the same flow, coarser) with its water
// moved by `solver` (a solver object), run for `end` seconds.
inline DamBreakResult run_dam_break(const nlohmann::json& solver, int threads, double end) {
  auto doc = load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  doc["materials"]["water"]["solver"] = solver;
  TestWorld tw(doc, threads);
  World& w = *tw.world;
  const Particles& p = w.particles();
  DamBreakResult r;
  r.liquid_at_start = p.count(ParticleType::Liquid);
  double iterations = 0;
  while (w.time() < end - 1e-12) {
    w.step(w.next_time_step_until(end));
    iterations += w.last_step().solver.iterations;
    r.max_avg_density_error =
        std::max(r.max_avg_density_error, w.last_step().solver.avg_density_error);
    ++r.steps;
  }
  r.mean_iterations = iterations / double(r.steps);
  r.liquid_at_end = p.count(ParticleType::Liquid);
  const double h = tw.scene.world.spacing;
  for (std::size_t i = 0; i < p.size(); ++i) {
    r.all_finite = r.all_finite && is_finite(p.position[i]) && is_finite(p.velocity[i]);
    if (p.type[i] != ParticleType::Liquid) continue;
    const Vec3& x = p.position[i];
    r.front_at_end = std::max(r.front_at_end, double(x.x));
    const bool inside = x.x > -0.5 * h && x.x < 1.6 + 0.5 * h && x.y > -0.5 * h &&
                        x.y < 1.0 + 0.5 * h && x.z > -0.5 * h && x.z < 0.4 + 0.5 * h;
    if (!inside && r.all_inside) r.first_outside = x;
    r.all_inside = r.all_inside && inside;
  }
  std::printf(
      "%llu steps, mean %.2f pressure iterations, largest avg density error %.4f, "
      "front at %.3f m\n",
      static_cast<unsigned long long>(r.steps), r.mean_iterations, r.max_avg_density_error,
      r.front_at_end);
  return r;
}

// What every fluid solver must keep in the dam break.
inline void expect_water_kept_in_tank(const DamBreakResult& r) {
  EXPECT_EQ(r.liquid_at_start, 15u * 20u * 10u);
  EXPECT_EQ(r.liquid_at_end, r.liquid_at_start);
  EXPECT_TRUE(r.all_finite) << "a position or velocity is NaN or infinite";
  EXPECT_TRUE(r.all_inside) << "a particle left the tank, at (" << r.first_outside.x << ", "
                            << r.first_outside.y << ", " << r.first_outside.z << ")";
  // The surge reached the far wall (it does so within ~0.5 s for a 0.8 m column).
  EXPECT_GT(r.front_at_end, 1.0);
}

}  // namespace upf::testing
