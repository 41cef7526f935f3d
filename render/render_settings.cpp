#include "render/render_settings.h"

#include <exception>
#include <memory>

#include "framework/core/errors.h"

#include "framework/scene/json_input.h"
#include "framework/scene/scene_section.h"
#include "framework/solver/registry.h"

namespace upf::render {

namespace {

struct RenderSectionData : SceneSectionData {
  RenderSettings settings;
};

constexpr int kMinPixels = 16, kMaxPixels = 8192;

}  // namespace

const char* wall_style_name(WallStyle style) {
  switch (style) {
    case WallStyle::Glass:
      return "glass";
    case WallStyle::Solid:
      return "solid";
    case WallStyle::Hidden:
      return "hidden";
  }
  return "glass";
}

std::optional<WallStyle> wall_style_named(const std::string& name) {
  for (WallStyle w : {WallStyle::Glass, WallStyle::Solid, WallStyle::Hidden})
    if (name == wall_style_name(w)) return w;
  return std::nullopt;
}

std::pair<int, int> parse_picture_size(const std::string& text, const std::string& option) {
  const auto x = text.find('x');
  int w = -1, h = -1;
  try {
    std::size_t used_w = 0, used_h = 0;
    if (x != std::string::npos) {
      w = std::stoi(text.substr(0, x), &used_w);
      h = std::stoi(text.substr(x + 1), &used_h);
      if (used_w != x || used_h != text.size() - x - 1) w = h = -1;
    }
  } catch (const std::exception&) {
    w = h = -1;
  }
  if (w < kMinPixels || h < kMinPixels || w > kMaxPixels || h > kMaxPixels)
    throw InputError(option, "\"" + text + "\": expected WIDTHxHEIGHT, each " +
                                 std::to_string(kMinPixels) + " to " + std::to_string(kMaxPixels) +
                                 " pixels (1280x720)");
  return {w, h};
}

void read_render_settings(const nlohmann::json& node, const std::string& path, JsonInput& input,
                          RenderSettings& settings) {
  if (!input.expect_object(node, path)) return;
  input.check_keys(
      node, path,
      {"camera", "width", "height", "samples", "color_by", "range", "walls", "surface"});
  if (auto it = node.find("camera"); it != node.end()) {
    const std::string where = JsonInput::child(path, "camera");
    if (input.expect_object(*it, where)) {
      input.check_keys(*it, where, {"position", "target", "up", "fov"});
      Camera c;
      const auto position = input.vec3(*it, where, "position", true);
      const auto target = input.vec3(*it, where, "target", true);
      c.up = input.vec3(*it, where, "up", false).value_or(c.up);
      c.fov_degrees = input.number(*it, where, "fov", c.fov_degrees, 1, 170, false, "degrees");
      if (position && target) {
        c.position = *position;
        c.target = *target;
        if ((c.target - c.position).norm() <= 0)
          input.problem(JsonInput::child(where, "target"),
                        "the camera looks at its own position: target must differ from position");
        else if (c.up.norm() <= 0)
          input.problem(JsonInput::child(where, "up"), "up must not be the zero vector");
        else
          settings.camera = c;
      }
    }
  }
  settings.width = int(
      input.number(node, path, "width", settings.width, kMinPixels, kMaxPixels, false, "pixels"));
  settings.height = int(
      input.number(node, path, "height", settings.height, kMinPixels, kMaxPixels, false, "pixels"));
  settings.samples_per_axis =
      int(input.number(node, path, "samples", settings.samples_per_axis, 1, 8, false));
  if (auto c = input.string(node, path, "color_by", false)) {
    if (c->empty())
      input.problem(JsonInput::child(path, "color_by"),
                    "expected \"type\", \"material\", \"speed\" or a field name");
    else
      settings.color_by = *c;
  }
  if (auto it = node.find("range"); it != node.end()) {
    const std::string where = JsonInput::child(path, "range");
    if (!it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number())
      input.problem(where, "expected [low, high], two numbers");
    else if ((*it)[0].get<double>() >= (*it)[1].get<double>())
      input.problem(where, "low must be below high");
    else
      settings.range = std::array<double, 2>{(*it)[0].get<double>(), (*it)[1].get<double>()};
  }
  if (auto w = input.string(node, path, "walls", false)) {
    if (auto style = wall_style_named(*w))
      settings.walls = *style;
    else
      input.problem(JsonInput::child(path, "walls"),
                    "unknown wall style \"" + *w + "\" (known: \"glass\", \"solid\", \"hidden\")");
  }
  if (auto it = node.find("surface"); it != node.end()) {
    if (it->is_boolean())
      settings.surface = it->get<bool>();
    else
      input.problem(JsonInput::child(path, "surface"),
                    "expected true or false, found " + json_type_name(*it));
  }
  // Whole numbers only: the size is a pixel count.
  for (const char* key : {"width", "height", "samples"}) {
    if (auto it = node.find(key);
        it != node.end() && it->is_number() && it->get<double>() != double(it->get<long long>()))
      input.problem(JsonInput::child(path, key), "expected a whole number");
  }
}

void register_render_section(Registry& registry) {
  SceneSection section;
  section.key = "render";
  section.summary = "how `upf render` and `upf run --render` draw the run's pictures";
  section.read = [](const nlohmann::json& node, const std::string& path, const SceneDescription&,
                    JsonInput& input) -> std::shared_ptr<const SceneSectionData> {
    auto data = std::make_shared<RenderSectionData>();
    read_render_settings(node, path, input, data->settings);
    return data;
  };
  section.build = [](World&, const SceneDescription&, const SceneSectionData&) {};
  registry.add_scene_section(std::move(section));
}

}  // namespace upf::render
