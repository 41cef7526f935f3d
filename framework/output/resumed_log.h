// Text logs of a resumed run (metrics.csv, probes.csv, bodies.csv): the file is cut back to its
// length at the checkpoint and reopened for appending, so the rows written after the checkpoint
// are written again, once.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>

namespace upf {

// Closes `log`, truncates `path` to `length` bytes and reopens it for appending. Throws
// OutputError naming the file when it cannot.
void reopen_log_at(std::ofstream& log, const std::filesystem::path& path, std::uintmax_t length);

}  // namespace upf
