// Checkpoint files: the full state of a run (checkpoint_state in simulation_run.cpp) behind a
// header that names the format and the build, and a checksum of the payload, written atomically
// (write to a temporary file, then rename) so a kill at any moment leaves the previous checkpoint
// whole. Reading checks the magic, format, build and checksum first: a checkpoint of another
// version or a damaged file is an InputError naming the file and what is wrong.
//
// Layout: "UPFCKPT\n", format (u32), build id (string), payload size (u64), FNV-1a 64 of the
// payload (u64), payload.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/state_stream.h"

namespace upf {

// 2: bodies keep their frame-mean forces; 3: the solvers' tables (DEM wall forces); 4: the
// scene's identity after the caller's header (simulation_run.cpp)
inline constexpr std::uint32_t kCheckpointFormat = 4;
inline constexpr const char* kCheckpointFileName = "checkpoint.upfck";

// "upf 0.1.0, Real float": runs resume only in the build flavour that wrote them.
std::string checkpoint_build_id();

// Throws OutputError when it cannot be written (the previous checkpoint stays).
void write_checkpoint(const std::filesystem::path& path, const std::vector<char>& payload);
// The payload, checked; throws InputError (file missing or not a regular file, other format or
// build, damaged). Reads nothing beyond what the file's size and header allow.
StateReader read_checkpoint(const std::filesystem::path& path);

}  // namespace upf
