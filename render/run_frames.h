// The frames of a finished (or stopped) run, as its particles.pvd lists them: one entry per
// time step with the files of its parts (particles, body meshes, liquid surface).
#pragma once

#include <filesystem>
#include <vector>

namespace upf::render {

struct RunFrame {
  double time = 0;
  std::vector<std::filesystem::path> parts;  // absolute or relative to the working directory
};

// Reads RUN_DIR/particles.pvd. Throws InputError naming the file when it is missing or malformed,
// or lists no frame.
std::vector<RunFrame> read_run_frames(const std::filesystem::path& run_dir);

}  // namespace upf::render
