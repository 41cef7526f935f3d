// Dam break with PCISPH (a coarse samples/dam_break.json): over 2 s of collapse, impact and
// run-up, mass is conserved (particle count constant), no particle leaves the tank (Akinci et al.
// 2012 boundaries), nothing becomes NaN, and the correction loop of Solenthaler & Pajarola 2009
// needs at most 10 iterations per step on average at eta = 1 % (their Fig. 9 reports 3-7).
#include <gtest/gtest.h>

#include <cmath>

#include "scene_helpers.h"

namespace upf {
namespace {

TEST(DamBreak, PcisphKeepsWaterInTankWithFewIterations) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;  // 3,000 liquid particles: the same flow, coarser
  testing::TestWorld tw(doc, 2);
  World& w = *tw.world;
  const Particles& p = w.particles();
  const std::size_t liquid = p.count(ParticleType::Liquid);
  const double h = tw.scene.world.spacing;
  ASSERT_EQ(liquid, 15u * 20u * 10u);

  double iterations = 0;
  std::uint64_t steps = 0;
  double front_at_end = 0;
  while (w.time() < 2.0 - 1e-12) {
    w.step(w.next_time_step_until(2.0));
    iterations += w.last_step().solver.iterations;
    ++steps;
  }
  ASSERT_EQ(p.count(ParticleType::Liquid), liquid);
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_TRUE(is_finite(p.position[i]) && is_finite(p.velocity[i])) << "particle " << p.id[i];
    if (p.type[i] != ParticleType::Liquid) continue;
    const Vec3& x = p.position[i];
    front_at_end = std::max(front_at_end, double(x.x));
    ASSERT_TRUE(x.x > -0.5 * h && x.x < 1.6 + 0.5 * h && x.y > -0.5 * h && x.y < 1.0 + 0.5 * h &&
                x.z > -0.5 * h && x.z < 0.4 + 0.5 * h)
        << "particle " << p.id[i] << " left the tank at t = " << w.time();
  }
  const double mean_iterations = iterations / double(steps);
  std::printf("%llu steps, mean %.2f pressure iterations\n", static_cast<unsigned long long>(steps),
              mean_iterations);
  EXPECT_LE(mean_iterations, 10.0);
  // The surge reached the far wall (it does so within ~0.5 s for a 0.8 m column).
  EXPECT_GT(front_at_end, 1.0);
}

}  // namespace
}  // namespace upf
