// Runs the `upf` program (UPF_EXECUTABLE) as a user would, for command-line tests.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace upf::testing {

struct UpfResult {
  int code;            // exit code, -1 when killed by a signal
  std::string output;  // stdout and stderr together
};

inline UpfResult run_upf(const std::string& args) {
  const std::string command = std::string(UPF_EXECUTABLE) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), int(buffer.size()), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

}  // namespace upf::testing
