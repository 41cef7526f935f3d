#include "render_command.h"

#include <unistd.h>

#include <cstdio>

#include "framework/core/errors.h"
#include "render/frame_picture.h"
#include "render/render_run.h"

namespace upf::app {

namespace {

int parse_whole(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  int v = -1;
  try {
    v = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || v < 0)
    throw InputError(option, "\"" + text + "\" is not a whole number >= 0");
  return v;
}

render::RenderOverrides overrides_of(const RenderArgs& args) {
  render::RenderOverrides o;
  if (!args.size.empty()) {
    const auto [w, h] = render::parse_picture_size(args.size, "--size");
    o.width = w;
    o.height = h;
  }
  if (args.samples) o.samples_per_axis = *args.samples;
  if (!args.color_by.empty()) o.color_by = args.color_by;
  if (!args.range.empty()) {
    if (args.range.size() != 2 || !(args.range[0] < args.range[1]))
      throw InputError("--range", "expected LOW,HIGH with LOW < HIGH");
    o.range = std::array<double, 2>{args.range[0], args.range[1]};
  }
  if (!args.walls.empty()) o.walls = render::wall_style_named(args.walls);
  if (args.surface) o.surface = true;
  return o;
}

}  // namespace

void add_render_options(CLI::App& command, RenderArgs& args) {
  command.add_option("--color-by", args.color_by,
                     "type, material, speed or a field of the frames (density, pressure, ...)");
  command.add_option("--size", args.size, "picture size WIDTHxHEIGHT (default 1280x720)");
  command.add_option("--samples", args.samples, "rays per pixel along each axis (default 2)")
      ->check(CLI::Range(1, 8));
  command.add_option("--range", args.range, "colour range LOW,HIGH (default: 1st-99th percentile)")
      ->delimiter(',');
  command.add_option("--walls", args.walls, "near walls: glass (default), solid or hidden")
      ->check(CLI::IsMember({"glass", "solid", "hidden"}));
  command.add_flag("--surface", args.surface,
                   "draw the liquid as water: its surface meshes (\"surface\" frames), "
                   "particles hidden");
  command.add_flag("--no-video", args.no_video, "pictures only, no MP4");
}

int render_command(const RenderArgs& args) {
  render::RenderRequest request;
  request.run_dir = args.run_dir;
  request.out_dir = args.out_dir;
  request.overrides = overrides_of(args);
  request.video = !args.no_video;
  request.threads = args.threads;
  if (!args.frames.empty()) {
    const auto colon = args.frames.find(':');
    if (colon == std::string::npos) {
      request.first_frame = request.last_frame = parse_whole(args.frames, "--frames");
    } else {
      const std::string a = args.frames.substr(0, colon), b = args.frames.substr(colon + 1);
      request.first_frame = a.empty() ? 0 : parse_whole(a, "--frames");
      request.last_frame = b.empty() ? -1 : parse_whole(b, "--frames");
    }
  }
  if (!args.quiet) {
    // A terminal gets one line rewritten in place; a pipe or a log gets plain lines, as from
    // `upf run`, at most one every 10 frames.
    const bool terminal = isatty(fileno(stderr)) != 0;
    request.on_frame = [terminal](int done, int total) {
      if (terminal) {
        std::fprintf(stderr, "\rrendering frame %d/%d", done, total);
        if (done == total) std::fprintf(stderr, "\n");
      } else if (done == total || done % 10 == 1) {
        std::fprintf(stderr, "rendering frame %d/%d\n", done, total);
      }
    };
  }
  const render::RenderOutcome out = render::render_run(request);
  const std::string dir =
      out.pictures.empty() ? std::string() : out.pictures.front().parent_path().string();
  std::printf("pictures: %zu in %s (%.1f s, coloured by %s", out.pictures.size(), dir.c_str(),
              out.seconds, render::field_label(out.color_by).c_str());
  if (out.range)
    std::printf(" from %.4g to %.4g: %s", (*out.range)[0], (*out.range)[1],
                out.range_source.c_str());
  std::printf(")\n");
  if (out.video)
    std::printf("video: %s\n", out.video->string().c_str());
  else
    std::printf("video: none (%s)\n", out.video_note.c_str());
  return 0;
}

}  // namespace upf::app
