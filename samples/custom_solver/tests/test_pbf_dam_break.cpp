// Dam break with PBF (samples/custom_solver/pbf_dam_break.json at 4 cm spacing): over 2 s of
// collapse, impact and run-up, mass is conserved (particle count constant), no particle leaves
// the tank (Akinci et al. 2012 boundaries, which PBF corrects against like any neighbour),
// nothing becomes NaN, and the surge reaches the far wall (Macklin & Müller 2013, Fig. 1 and 5:
// the same flow as the SPH solvers, at the paper's 4 iterations).
#include <gtest/gtest.h>

#include "pbf_test_world.h"
#include "tests/physics/tank_checks.h"

namespace upf::pbf {
namespace {

TEST(PbfDamBreak, KeepsWaterInTankFor2Seconds) {
  auto doc = upf::testing::load_sample_json("custom_solver/pbf_dam_break.json");
  doc["particle_spacing"] = 0.04;  // 3,000 liquid particles: the same flow, coarser
  auto tw = testing::pbf_world(doc, 2);
  const upf::testing::TankRun r = upf::testing::run_in_tank(tw, 2.0);
  const Particles& p = tw.world->particles();
  ASSERT_EQ(r.liquid_before, 15u * 20u * 10u);
  EXPECT_EQ(r.liquid_after, r.liquid_before);
  EXPECT_FALSE(r.not_finite) << "particle " << p.id[r.not_finite.value_or(0)];
  EXPECT_FALSE(r.outside) << "particle " << p.id[r.outside.value_or(0)] << " left the tank";
  std::printf(
      "%llu steps, %.0f iterations each, mean avg density error %.5f, largest %.5f, "
      "front at %.3f m\n",
      static_cast<unsigned long long>(r.steps), r.mean_iterations, r.mean_avg_density_error,
      r.max_avg_density_error, r.front);
  EXPECT_GT(r.front, 1.0);
}

}  // namespace
}  // namespace upf::pbf
