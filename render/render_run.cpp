#include "render/render_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include <unistd.h>

#include "framework/core/child_process.h"
#include "framework/core/errors.h"
#include "framework/output/atomic_file.h"
#include "framework/run/run_manifest.h"
#include "framework/scene/json_input.h"
#include "render/frame_picture.h"
#include "render/run_frames.h"
#include "render/scene_facts.h"

namespace upf::render {

namespace {

namespace fs = std::filesystem;

// The particle spacing of a run without scene.json (older runs): the median distance from a
// sample of particles to their nearest neighbours, which on a lattice is the spacing.
double estimate_spacing(const PolyData& p) {
  std::vector<double> nearest;
  const std::size_t step = std::max<std::size_t>(1, p.points.size() / 200);
  for (std::size_t i = 0; i < p.points.size(); i += step) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < p.points.size(); ++j) {
      const double d = double((p.points[i] - p.points[j]).norm());
      if (j != i && d > 0) best = std::min(best, d);
    }
    if (best < std::numeric_limits<double>::max()) nearest.push_back(best);
  }
  if (nearest.empty()) return 0.02;
  std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(nearest.size() / 2),
                   nearest.end());
  return nearest[nearest.size() / 2];
}

// The 1st and 99th percentiles of the field over the moving particles, widest over all frames,
// so every picture of a run shares one scale.
std::array<double, 2> auto_range(const std::vector<RunFrame>& frames, const std::string& field) {
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const RunFrame& f : frames) {
    if (auto r = field_percentiles(read_vtp(f.parts.front()), field)) {
      low = std::min(low, (*r)[0]);
      high = std::max(high, (*r)[1]);
    }
  }
  if (low > high) return {0, 1};
  return widened_if_flat({low, high});
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

}  // namespace

RenderOutcome render_run(const RenderRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  SceneFacts facts =
      read_scene_facts(scene_record(request.run_dir), run_directory_name(request.run_dir));
  RenderSettings settings = facts.settings;
  const RenderOverrides& o = request.overrides;
  if (o.width) settings.width = *o.width;
  if (o.height) settings.height = *o.height;
  if (o.samples_per_axis) settings.samples_per_axis = *o.samples_per_axis;
  // The scene's range belongs to the scene's color_by: another field gets its own range.
  if (o.color_by && *o.color_by != settings.color_by) settings.range.reset();
  if (o.color_by) settings.color_by = *o.color_by;
  if (o.range) settings.range = o.range;
  if (o.walls) settings.walls = *o.walls;
  if (o.surface) settings.surface = *o.surface;

  std::vector<RunFrame> frames = read_run_frames(request.run_dir);
  const int last = request.last_frame < 0 ? int(frames.size()) - 1
                                          : std::min(request.last_frame, int(frames.size()) - 1);
  if (request.first_frame < 0 || request.first_frame > last)
    throw InputError("--frames", "the run has frames 0 to " + std::to_string(frames.size() - 1));
  frames = std::vector<RunFrame>(frames.begin() + request.first_frame, frames.begin() + last + 1);

  const FrameData first = read_frame(frames.front());
  if (settings.surface && !has_liquid_surface(first))
    throw InputError(request.run_dir.string(),
                     "--surface draws the liquid's surface meshes, and this run has none: add "
                     "\"surface\" to the scene's /output/formats and run it again");
  PictureContext context;
  std::string range_source;
  context.settings = settings;
  context.title = facts.name;
  context.threads = request.threads;
  context.particle_spacing = facts.spacing.value_or(estimate_spacing(first.particles));
  if (settings.color_by != "type" && settings.color_by != "material") {
    if (!frame_has_field(first.particles, settings.color_by)) {
      std::string known;
      for (const auto& name : colour_choices(first.particles))
        known += (known.empty() ? "\"" : ", \"") + name + "\"";
      throw InputError("color_by", "the frames have no field \"" + settings.color_by +
                                       "\" (known: " + known + ")");
    }
    const auto range = settings.range.value_or(auto_range(frames, settings.color_by));
    context.scale = ColourScale{settings.color_by, range[0], range[1]};
    range_source = o.range          ? "--range"
                   : settings.range ? "the scene's render.range"
                                    : "1st-99th percentile over the frames";
  }
  if (settings.camera) {
    context.camera = *settings.camera;
  } else {
    context.camera =
        camera_for_particles(first.particles, facts.up, double(settings.width) / settings.height);
  }

  // The pictures are recorded like the run's files (run_manifest.h): into RUN_DIR/render in the
  // run's manifest, or into a folder of their own with its own manifest.
  const fs::path out_dir = request.out_dir.empty() ? request.run_dir / "render" : request.out_dir;
  std::optional<RunManifest> manifest;
  std::string prefix;
  if (request.out_dir.empty()) {
    manifest.emplace(RunManifest::for_continued_run(request.run_dir));
    manifest->claim_directory("render");
    prefix = "render/";
  } else {
    manifest.emplace(RunManifest::for_new_run(out_dir, false));
    manifest->clear_previous();
  }
  RenderOutcome outcome;
  outcome.color_by = settings.color_by;
  if (context.scale) outcome.range = std::array<double, 2>{context.scale->low, context.scale->high};
  outcome.range_source = range_source;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const FrameData data = k == 0 ? first : read_frame(frames[k]);
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.png", request.first_frame + int(k));
    manifest->claim(prefix + name);
    write_png(out_dir / name, draw_frame(data, context));
    outcome.pictures.push_back(out_dir / name);
    if (request.on_frame) request.on_frame(int(k) + 1, int(frames.size()));
  }

  if (!request.video) {
    outcome.video_note = "not asked for";
  } else if (frames.size() < 2) {
    outcome.video_note = "one frame only";
  } else if (!on_path("ffmpeg")) {
    outcome.video_note = "ffmpeg is not installed (apt-get install ffmpeg)";
  } else {
    double fps = facts.fps.value_or(0);
    if (fps <= 0) {
      const double span = frames.back().time - frames.front().time;
      fps = span > 0 ? double(frames.size() - 1) / span : 30;
    }
    manifest->claim({prefix + facts.name + ".mp4", prefix + "ffmpeg.log"});
    const fs::path video = out_dir / (facts.name + ".mp4");
    const fs::path partial = out_dir / (facts.name + ".mp4.tmp");
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", fps);
    const ChildExit ffmpeg = spawn_and_wait(
        {"ffmpeg", "-y", "-loglevel", "error", "-framerate", rate, "-start_number",
         std::to_string(request.first_frame), "-i", (out_dir / "frame_%05d.png").string(),
         // H.264 wants even sizes and 4:2:0 for players to accept it.
         "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-f",
         "mp4", partial.string()},
        out_dir / "ffmpeg.log");
    std::error_code ec;
    if (ffmpeg.started && ffmpeg.code == 0) {
      fs::rename(partial, video, ec);
      if (ec) throw OutputError("cannot write '" + video.string() + "': " + ec.message());
      fs::remove(out_dir / "ffmpeg.log", ec);
      outcome.video = video;
    } else {
      fs::remove(partial, ec);
      outcome.video_note =
          ffmpeg.started ? "ffmpeg failed: " + last_line(out_dir / "ffmpeg.log") : ffmpeg.error;
    }
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace upf::render
