// The run's checkpoint schedule with an interval far below a step (issue 46, item 6): it stepped
// to the next checkpoint time by additions, 1e-300 s at a time, and never returned: 100% CPU,
// no step, deaf to Ctrl-C. The command line now refuses such intervals; the schedule itself
// must not hang for a caller that passes one (the library, the Python module). SIGALRM ends
// this test's process should it hang again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "framework/checkpoint/checkpoint_file.h"
#include "framework/run/simulation_run.h"
#include "tests/physics/scene_helpers.h"

namespace upf {
namespace {

namespace fs = std::filesystem;

TEST(CheckpointSchedule, AnIntervalFarBelowAStepCheckpointsEveryStepInsteadOfHanging) {
  const Registry registry = testing::builtin_registry();
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.1;
  const SceneDescription scene = read_scene(doc, registry, "test");
  for (const bool wall_clock : {true, false}) {
    const fs::path out =
        fs::temp_directory_path() / ("upf_checkpoint_schedule_" + std::to_string(int(wall_clock)));
    fs::remove_all(out);
    RunOptions options;
    options.out_dir = out;
    options.threads = 1;
    options.end_time = 0.02;
    options.write_frames = false;
    options.final_checkpoint = false;
    options.checkpoint = {1e-300, wall_clock};
    ::alarm(120);
    const RunResult r = run_simulation(scene, registry, options);
    ::alarm(0);
    EXPECT_EQ(r.status, "completed") << (wall_clock ? "wall-clock" : "simulated");
    EXPECT_GT(r.steps, 1u);
    EXPECT_TRUE(fs::exists(out / kCheckpointFileName)) << "one was due at every step";
    fs::remove_all(out);
  }
}

}  // namespace
}  // namespace upf
