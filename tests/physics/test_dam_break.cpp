// Dam break with PCISPH (a coarse samples/dam_break.json): over 2 s of collapse, impact and
// run-up, mass is conserved (particle count constant), no particle leaves the tank (Akinci et al.
// 2012 boundaries), nothing becomes NaN, and the correction loop of Solenthaler & Pajarola 2009
// needs at most 10 iterations per step on average at eta = 1 % (their Fig. 9 reports 3-7).
#include <gtest/gtest.h>

#include "tank_checks.h"

namespace upf {
namespace {

TEST(DamBreak, PcisphKeepsWaterInTankWithFewIterations) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;  // 3,000 liquid particles: the same flow, coarser
  testing::TestWorld tw(doc, 2);
  const testing::TankRun r = testing::run_in_tank(tw, 2.0);
  const Particles& p = tw.world->particles();
  ASSERT_EQ(r.liquid_before, 15u * 20u * 10u);
  EXPECT_EQ(r.liquid_after, r.liquid_before);
  EXPECT_FALSE(r.not_finite) << "particle " << p.id[r.not_finite.value_or(0)];
  EXPECT_FALSE(r.outside) << "particle " << p.id[r.outside.value_or(0)] << " left the tank";
  std::printf("%llu steps, mean %.2f pressure iterations\n",
              static_cast<unsigned long long>(r.steps), r.mean_iterations);
  EXPECT_LE(r.mean_iterations, 10.0);
  // The surge reached the far wall (it does so within ~0.5 s for a 0.8 m column).
  EXPECT_GT(r.front, 1.0);
}

}  // namespace
}  // namespace upf
