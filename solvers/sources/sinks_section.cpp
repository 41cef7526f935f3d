#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/world/world.h"
#include "solvers/sources/json_array.h"
#include "solvers/sources/sink.h"
#include "solvers/sources/sources_section.h"

namespace upf {

namespace {

using nlohmann::json;

struct SinksData : SceneSectionData {
  std::vector<SinkDesc> sinks;
};

std::optional<SinkDesc> read_sink(JsonInput& in, const json& s, const std::string& where,
                                  std::size_t index) {
  in.check_keys(s, where, {"name", "min", "max", "point", "normal"});
  SinkDesc sink;
  sink.name = in.string(s, where, "name", false).value_or("sink " + std::to_string(index));
  const bool is_box = s.contains("min") || s.contains("max");
  if (is_box == (s.contains("point") || s.contains("normal"))) {
    in.problem(where,
               "a sink is a box (\"min\", \"max\") or a half-space (\"point\", "
               "\"normal\"): give one of the two");
    return std::nullopt;
  }
  if (is_box) {
    const auto lo = in.vec3(s, where, "min", true), hi = in.vec3(s, where, "max", true);
    if (!lo || !hi) return std::nullopt;
    if (!(lo->array() < hi->array()).all()) {
      in.problem(JsonInput::child(where, "max"), "max must exceed min on every axis");
      return std::nullopt;
    }
    sink.box = Box{*lo, *hi};
    return sink;
  }
  const auto point = in.vec3(s, where, "point", true), normal = in.vec3(s, where, "normal", true);
  if (!point || !normal) return std::nullopt;
  if (!(normal->norm() > 0)) {
    in.problem(JsonInput::child(where, "normal"), "the normal must not be zero");
    return std::nullopt;
  }
  sink.point = *point;
  sink.normal = normal->normalized();
  return sink;
}

std::shared_ptr<const SceneSectionData> read_sinks(const json& node, const std::string& path,
                                                   const SceneDescription&, JsonInput& in) {
  auto data = std::make_shared<SinksData>();
  const bool ok = read_each(node, path, in, "sinks",
                            [&](const json& s, const std::string& where, std::size_t i) {
                              auto sink = read_sink(in, s, where, i);
                              if (sink) data->sinks.push_back(*sink);
                              return sink.has_value();
                            });
  if (!ok) return nullptr;
  return data;
}

void build_sinks(World& world, const SceneDescription&, const SceneSectionData& section) {
  for (const auto& s : static_cast<const SinksData&>(section).sinks)
    world.add_source(std::make_unique<Sink>(s));
}

}  // namespace

SceneSection sinks_scene_section() {
  return {"sinks", "boxes and half-spaces where liquid leaves the scene (docs/emitters.md)",
          read_sinks, build_sinks};
}

}  // namespace upf
