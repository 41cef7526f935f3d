// The subcommands of `upf`.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace upf::app {

struct RunArgs {
  std::string scene;
  std::string out_dir;
  int threads = 0;
  std::optional<double> end_time;
  bool quiet = false;
  bool no_frames = false;
};

int run_command(const RunArgs& args);
int validate_command(const std::vector<std::string>& files);
int info_command();

}  // namespace upf::app
