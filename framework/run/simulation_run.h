// Runs a scene from start to end: builds the world, steps it, and writes frames (.vtp + .pvd),
// metrics.csv, probes.csv and summary.json into the output directory. An instability writes the
// last good frame and a summary saying what went wrong, then throws InstabilityError.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/run/frame_writer.h"
#include "framework/run/run_manifest.h"
#include "framework/scene/scene.h"
#include "framework/solver/registry.h"
#include "framework/world/device_pipeline.h"
#include "framework/world/particle_domain.h"
#include "framework/world/world.h"

namespace upf {

struct RunProgress {
  double time = 0, end_time = 0;
  std::uint64_t steps = 0;  // since the run began, resumed parts included
  // This process's share: a resumed run's rates and ETA count only what it did itself.
  double start_time = 0;
  std::uint64_t steps_this_process = 0;
  double wall_seconds = 0;
  // The CPU threads the steps use now: fewer than asked for while the machine is busy.
  int threads = 0;
};

// When a run writes checkpoints (checkpoint_file.h) into its output directory.
struct CheckpointPolicy {
  double every = 0;        // s between checkpoints; 0: only when stopped (stop_requested)
  bool wall_clock = true;  // wall-clock seconds, else simulated seconds
};

// What a run's frames will take on disk, known before its first step (FrameWriter's sizes).
struct OutputEstimate {
  int frames = 0;  // still to be written by this run
  std::uint64_t bytes_per_frame = 0;
  std::uint64_t bytes_once = 0;  // the frozen piece
  std::uint64_t total_bytes = 0;
  bool compressed = false;  // the figures are the uncompressed sizes, an upper bound
  bool surface = false;     // surface meshes come on top, their size unknown beforehand
};

struct RunOptions {
  std::filesystem::path out_dir = "out";
  int threads = 0;  // 0: OpenMP's default
  // Fewer threads while other processes take cores (thread_share_watch.h); false keeps them all.
  bool follow_free_cores = true;
  std::optional<double> end_time;  // overrides the scene's time.end
  bool write_frames = true;
  std::function<void(const RunProgress&)> on_progress;  // called after every step
  std::function<void(const World&)> on_step;            // tests and tools look at the world
  // Called once before anything but upf_scene.json is written, when the run writes frames.
  std::function<void(const OutputEstimate&)> on_output_estimate;
  // False: an instability ends the run with status "unstable" instead of throwing, so a
  // comparison keeps the figures of the steps that did succeed.
  bool throw_on_instability = true;
  CheckpointPolicy checkpoint;
  // A completed run leaves its final state as the checkpoint, so that `--resume --end` can
  // extend it; comparisons, whose runs are never resumed, turn it off.
  bool final_checkpoint = true;
  // Kept at the head of every checkpoint for the caller: the command line stores the scene and
  // its options there, so `upf run --resume DIR` needs nothing else (read_checkpoint_header).
  std::string checkpoint_header;
  // The scene file's text: kept as out_dir/upf_scene.json once the run's checks have passed
  // (not on resume), so tools such as `upf render` know the scene a run directory came from.
  // On resume it must be the scene recorded there: a checkpoint of another scene is refused.
  std::string scene_text;
  // A new run into a non-empty folder that no upf run recorded (run_manifest.h): false refuses
  // it; true replaces the files at the names the run writes and removes nothing else.
  bool overwrite = false;
  // Continue the run whose checkpoint is in out_dir, with the scene it was made from.
  bool resume = false;
  // Polled after every step: true ends the run after a checkpoint (status "interrupted").
  std::function<bool()> stop_requested;
  // Needed when the scene asks for the "surface" format; unset: such a scene is bad input.
  VdbFrameWriters vdb_writers;
  // Where the steps run: unset, the CPU executor; else the device pipeline it makes for the
  // prepared world (device/device_pipelines.h), before anything is written. It may throw
  // InputError (a scene the pipeline does not cover, no GPU).
  std::function<std::unique_ptr<DevicePipeline>(const World&)> make_device;
  // Splits the prepared world over MPI ranks (framework/mpi/): every rank runs the same scene
  // with the same options; rank 0 gathers the particles and writes every file, the others write
  // nothing. Unset: one rank.
  std::function<std::unique_ptr<ParticleDomain>(const World&)> make_domain;
};

struct RunResult {
  std::string status = "completed";  // or "unstable", or "interrupted" (resumable)
  // A resumed run that had already reached its end: nothing was simulated or written.
  bool already_complete = false;
  std::string failure;
  std::uint64_t steps = 0;
  double simulated_time = 0;  // unstable: the time the failed step reached
  int threads = 0;
  // The threads this process's steps used, on average: fewer than `threads` while other
  // processes took cores (RunOptions::follow_free_cores).
  double mean_threads = 0;
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
  // Files of an earlier run in the same directory (its manifest's), removed before this one
  // wrote anything.
  std::size_t replaced_files = 0;
  int checkpoints = 0;                    // written by this process
  std::filesystem::path checkpoint_file;  // the last one written, if any
};

// The caller's header of the checkpoint in `run_dir` (see RunOptions::checkpoint_header); throws
// InputError when there is none, or it is of another build or damaged.
std::string read_checkpoint_header(const std::filesystem::path& run_dir);

RunResult run_simulation(const SceneDescription& scene, const Registry& registry,
                         const RunOptions& options);

// The same run over a world the caller built from `scene` and prepared (the Python module's
// Simulation.run): from the world's current time to the end, its first frame the state now.
// With options.resume the world is first restored from the checkpoint in out_dir.
RunResult run_world(World& world, const SceneDescription& scene, const RunOptions& options);

}  // namespace upf
