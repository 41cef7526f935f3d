// World::next_time_step_until: steps up to a frame time. Reference: the scene format's promise
// (docs/scene-format.md, /time/fixed_dt) that every step uses fixed_dt when it is set; with a
// frame interval that is a whole number of fixed steps, no step may be shortened.
#include <gtest/gtest.h>

#include "framework/world/world.h"

namespace upf {
namespace {

TEST(WorldTimeStep, FixedStepsThatDivideTheFrameIntervalAreNeverShortened) {
  WorldSettings settings;
  settings.time.fixed_dt = 0.002;
  World world(settings, 1);
  world.prepare();
  int steps = 0;
  for (int frame = 1; frame <= 25; ++frame) {  // 500 frames per second up to 0.05 s
    const double frame_time = frame * 0.002;
    while (world.time() < frame_time - 1e-12) {
      const double dt = world.next_time_step_until(frame_time);
      EXPECT_NEAR(dt, 0.002, 1e-12) << "step " << steps;
      world.step(dt);
      ++steps;
    }
  }
  EXPECT_EQ(steps, 25);
}

TEST(WorldTimeStep, StepsSpreadEvenlyOverWhatRemainsOfTheFrame) {
  WorldSettings settings;
  settings.time.fixed_dt = 0.004;
  World world(settings, 1);
  world.prepare();
  // 0.01 s left at most 0.004 s per step: three equal steps of 0.01 / 3.
  EXPECT_NEAR(world.next_time_step_until(0.01), 0.01 / 3, 1e-15);
  EXPECT_NEAR(world.next_time_step_until(0.003), 0.003, 1e-15);
}

}  // namespace
}  // namespace upf
