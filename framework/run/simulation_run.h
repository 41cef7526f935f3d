// Runs a scene from start to end: builds the world, steps it, and writes frames (.vtp + .pvd),
// metrics.csv, probes.csv and summary.json into the output directory. An instability writes the
// last good frame and a summary saying what went wrong, then throws InstabilityError.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "framework/scene/scene.h"
#include "framework/solver/registry.h"
#include "framework/world/world.h"

namespace upf {

struct RunProgress {
  double time = 0, end_time = 0;
  std::uint64_t steps = 0;
  double wall_seconds = 0;
};

struct RunOptions {
  std::filesystem::path out_dir = "out";
  int threads = 0;                 // 0: OpenMP's default
  std::optional<double> end_time;  // overrides the scene's time.end
  bool write_frames = true;
  std::function<void(const RunProgress&)> on_progress;  // called after every step
  std::function<void(const World&)> on_step;            // tests and tools look at the world
  // False: an instability ends the run with status "unstable" instead of throwing, so a
  // comparison keeps the figures of the steps that did succeed.
  bool throw_on_instability = true;
};

struct RunResult {
  std::string status = "completed";  // or "unstable"
  std::string failure;
  std::uint64_t steps = 0;
  double simulated_time = 0;  // unstable: the time the failed step reached
  int threads = 0;
  double wall_seconds = 0;
  std::size_t liquid_particles = 0;
  std::size_t total_particles = 0;
  int frames = 0;
  double mean_dt = 0;
  double mean_iterations = 0;
  int max_iterations = 0;
  double mean_avg_density_error = 0;
  double max_density_error = 0;
  double fluid_particle_steps_per_second = 0;
  std::vector<std::pair<std::string, double>> final_probes;
};

RunResult run_simulation(const SceneDescription& scene, const Registry& registry,
                         const RunOptions& options);

}  // namespace upf
