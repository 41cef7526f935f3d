// `upf render RUN_DIR`: one PNG per saved frame of a run, and an MP4 of them when ffmpeg is
// installed. Reads the frames the run listed in particles.pvd and the scene copy the run keeps
// (scene.json: its name, particle spacing, gravity, frame rate and "render" section).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/render_settings.h"

namespace upf::render {

// What the command line may change; absent: the scene's "render" section, else the default.
struct RenderOverrides {
  std::optional<int> width, height, samples_per_axis;
  std::optional<std::string> color_by;
  std::optional<std::array<double, 2>> range;
  std::optional<WallStyle> walls;
  std::optional<bool> surface;
};

struct RenderRequest {
  std::filesystem::path run_dir;
  std::filesystem::path out_dir;  // empty: RUN_DIR/render
  RenderOverrides overrides;
  int first_frame = 0;
  int last_frame = -1;  // -1: the last one
  bool video = true;    // an MP4 when ffmpeg is on PATH
  int threads = 0;
  std::function<void(int done, int total)> on_frame;
};

struct RenderOutcome {
  std::vector<std::filesystem::path> pictures;
  std::optional<std::filesystem::path> video;
  std::string video_note;  // why there is no video, when there is none
  std::string color_by;
  std::optional<std::array<double, 2>> range;  // the field range used, when colouring by field
  // Where the range came from: "--range", "the scene's render.range", or "1st-99th percentile
  // over the frames".
  std::string range_source;
  double seconds = 0;
};

// Throws InputError (a missing or damaged run, an unknown field, a bad "render" section in
// scene.json) or OutputError (pictures that cannot be written).
RenderOutcome render_run(const RenderRequest& request);

}  // namespace upf::render
