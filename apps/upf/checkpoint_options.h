// The command line's side of checkpoints: `--checkpoint-every` durations, and the header that
// every checkpoint of `upf run` carries (the scene file's text and the run's options as JSON), so
// `upf run --resume DIR` rebuilds the same run from the directory alone.
#pragma once

#include <optional>
#include <string>

#include "framework/run/simulation_run.h"

namespace upf::app {

// The intervals --checkpoint-every allows, in seconds (wall-clock or simulated).
inline constexpr double kMinWallClockEvery = 1;
inline constexpr double kMinSimulatedEvery = 1e-6;
inline constexpr double kMaxCheckpointEvery = 1e9;

// "300s", "5m", "2h": wall-clock time; "0.5sim": simulated seconds. Throws InputError naming
// --checkpoint-every and the forms it takes, or the allowed range above.
CheckpointPolicy parse_checkpoint_every(const std::string& text);

struct ResumableRun {
  std::string scene_text;    // the scene file as it was when the run started
  std::string scene_source;  // its path (relative mesh files resolve against it)
  std::string solver;        // --solver, or empty
  std::optional<double> end_time;
  bool no_frames = false;
  std::string checkpoint_every;  // as given, or empty
};

std::string to_header(const ResumableRun& run);
// Throws InputError naming `where` when the header is not one of ours.
ResumableRun from_header(const std::string& header, const std::string& where);

}  // namespace upf::app
