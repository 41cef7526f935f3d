// `upf render RUN_DIR` and `upf run --render`: pictures (and an MP4) of a run's saved frames.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace upf::app {

struct RenderArgs {
  std::string run_dir;
  std::string out_dir;  // empty: RUN_DIR/render
  std::string color_by;
  std::string size;  // "WIDTHxHEIGHT"
  std::optional<int> samples;
  std::vector<double> range;
  std::string walls;
  bool surface = false;
  std::string frames;  // "N" or "A:B" (either end may be empty)
  bool no_video = false;
  int threads = 0;
  bool quiet = false;
};

// The options of `upf render` (also used by `upf run --render` for the look of the pictures).
void add_render_options(CLI::App& command, RenderArgs& args);

// Renders and prints where the pictures went. Throws InputError for bad options or a bad run.
int render_command(const RenderArgs& args);

}  // namespace upf::app
