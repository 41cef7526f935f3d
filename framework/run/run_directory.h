// A run's output directory. A new run into a directory that holds an earlier run first removes
// that run's files, so that importers reading frames/ or particles.pvd never mix two runs (a
// shorter run would otherwise leave the earlier run's later frames behind). Only upf's own file
// names go: anything else the user keeps there stays.
#pragma once

#include <cstddef>
#include <filesystem>

namespace upf {

// Removes an earlier run's files from `dir`: particles.pvd, metrics.csv, probes.csv,
// bodies.csv, summary.json, scene.json, the checkpoint, frames/{frame,surface,bodies}_NNNNN.*,
// and render/frame_NNNNN.png with render/*.mp4. Returns how many files went.
std::size_t clear_earlier_run(const std::filesystem::path& dir);

}  // namespace upf
