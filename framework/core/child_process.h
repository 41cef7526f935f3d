// Runs a helper program (the plotting script, ffmpeg) as a child process, never through a shell,
// with its stdout and stderr appended to a log file, and waits for it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace upf {

struct ChildExit {
  bool started = false;
  int code = -1;  // exit status, or -1 when killed by a signal
  std::string error;
};

// argv[0] is looked up on PATH (posix_spawnp).
ChildExit spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log);

// The last non-empty line of `log`: a failed program's error message, usually.
std::string last_line(const std::filesystem::path& log);

}  // namespace upf
