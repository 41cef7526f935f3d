// Determinism of the PBF sample (DESIGN.md, "Determinism"): Jacobi iterations in which every
// particle gathers from its neighbours in list order and writes only itself, and a fixed-point
// error sum, give bitwise identical results for 1 and 2 threads. Vorticity confinement is on so
// that every pass of the solver is covered.
#include <gtest/gtest.h>

#include "pbf_test_world.h"

namespace upf::pbf {
namespace {

upf::testing::StateById run_steps(int threads, int steps) {
  auto doc = testing::with_pbf("dam_break.json", {{"vorticity", 0.05}});
  doc["particle_spacing"] = 0.04;
  auto tw = testing::pbf_world(doc, threads);
  for (int s = 0; s < steps; ++s) tw.world->step(tw.world->next_time_step());
  return upf::testing::state_by_id(tw.world->particles());
}

TEST(PbfDeterminism, OneAndTwoThreadsGiveBitwiseIdenticalStates) {
  const auto one = run_steps(1, 200), two = run_steps(2, 200), start = run_steps(1, 0);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(upf::testing::bitwise_differences(one, two), 0u)
      << "particles whose position or velocity differ in some bit";
  // The run must actually have moved: a frozen world would pass trivially.
  EXPECT_GT(upf::testing::bitwise_differences(one, start, true), 1000u);
}

}  // namespace
}  // namespace upf::pbf
