// `upf view SCENE_OR_RUN`: an interactive window over a saved run (its frames, with a slider) or
// a scene file stepped live (with its solver parameters editable; changes restart the run).
//
// The picture is drawn by the same Embree ray tracer as `upf render` (render/frame_picture.h),
// at the window's size with one sample per pixel, and shown as one texture behind the Dear ImGui
// panel: one renderer for pictures and viewer, so what the window shows is what `upf render`
// writes. OpenGL (the legacy OpenGL 2 ImGui backend, which Mesa's llvmpipe runs under Xvfb) only
// puts that texture and the panel on the screen.
#pragma once

#include <filesystem>
#include <string>

#include "framework/solver/registry.h"

namespace upf::viewer {

struct ViewOptions {
  std::filesystem::path input;       // a run directory (has particles.pvd) or a scene file
  std::string size = "1280x720";     // window size WIDTHxHEIGHT
  std::filesystem::path screenshot;  // scripted: write the window's pixels here, then exit
  int exit_after = 0;                // close after this many drawn frames (0: when closed)
  int threads = 0;
  bool play = false;  // start playing
};

// The message `upf view` gives (exit code 1) when no window can be opened.
std::string no_display_message();

// Returns the exit code: 0, or 1 without a display. Throws InputError for a bad input or size,
// OutputError when the screenshot cannot be written.
int run_viewer(const ViewOptions& options, const Registry& registry);

}  // namespace upf::viewer
