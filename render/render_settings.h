// How a run's pictures look: camera, size, colouring. Read from the scene file's optional
// "render" section (docs/scene-format.md), then overridden by `upf render`'s options.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "render/camera.h"

namespace upf {
class JsonInput;
class Registry;
}  // namespace upf

namespace upf::render {

enum class WallStyle { Glass, Solid, Hidden };

struct RenderSettings {
  std::optional<Camera> camera;  // absent: one that frames every particle of the first frame
  int width = 1280, height = 720;
  int samples_per_axis = 2;
  // "type", "material", "speed" (the velocity's length) or an exported field of the frames
  // (a vector field is shown by its length).
  std::string color_by = "type";
  std::optional<std::array<double, 2>> range;  // absent: the 1st..99th percentile over the run
  WallStyle walls = WallStyle::Glass;          // frozen particles on the camera's side
  // Water: the liquid drawn as its surface mesh ("surface" frames), shaded as water, and its
  // particles hidden. Off: the liquid's particles, and no surface mesh.
  bool surface = false;
};

// "glass", "solid", "hidden": the names scene files, `upf render --walls` and the viewer use.
const char* wall_style_name(WallStyle style);
std::optional<WallStyle> wall_style_named(const std::string& name);

// Parses "WIDTHxHEIGHT" (each a whole number of 16 to 8192 pixels, the "render" section's
// range). Throws InputError naming `option` otherwise.
std::pair<int, int> parse_picture_size(const std::string& text, const std::string& option);

// Reads the "render" object at JSON path `path` into `settings` (keys absent keep their value).
// Every problem goes to `input`.
void read_render_settings(const nlohmann::json& node, const std::string& path, JsonInput& input,
                          RenderSettings& settings);

// Lets scene files carry a "render" section (`upf validate` checks it; runs ignore it).
void register_render_section(Registry& registry);

}  // namespace upf::render
