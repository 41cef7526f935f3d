#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/world/world.h"
#include "solvers/sources/emitter.h"
#include "solvers/sources/json_array.h"
#include "solvers/sources/sink.h"
#include "solvers/sources/sources_section.h"

namespace upf {

namespace {

using nlohmann::json;

struct SinksData : SceneSectionData {
  std::vector<SinkDesc> sinks;
};

// "outflow": {"direction": [1, 0, 0], "buffer": 4, "velocity": "extrapolated" or m/s}: the
// outflow buffer upstream of a box sink's face (outflow_buffer.h).
std::optional<OutflowBufferDesc> read_outflow(JsonInput& in, const json& s, const std::string& path,
                                              const Box& box, double h) {
  const std::string where = JsonInput::child(path, "outflow");
  const json& o = s.at("outflow");
  if (!in.expect_object(o, where)) return std::nullopt;
  in.check_keys(o, where, {"direction", "buffer", "velocity"});
  const auto direction = in.vec3(o, where, "direction", true);
  const double buffer = in.number(o, where, "buffer", 4, 1, 50, false, "spacings");
  if (!direction) return std::nullopt;
  OutflowBufferDesc d;
  int axis = -1;
  for (int a = 0; a < 3; ++a)
    if ((*direction)[a] != 0 && (*direction)[(a + 1) % 3] == 0 && (*direction)[(a + 2) % 3] == 0)
      axis = a;
  if (axis < 0) {
    in.problem(JsonInput::child(where, "direction"),
               "the outflow goes along a world axis: [1, 0, 0], [0, -1, 0], ... (the box's face "
               "across it is the outlet)");
    return std::nullopt;
  }
  d.axis = axis;
  d.sign = (*direction)[axis] > 0 ? 1.0 : -1.0;
  d.face = d.sign > 0 ? box.min[axis] : box.max[axis];
  d.length = buffer * h;
  d.reference = 2 * h;
  if (auto v = o.find("velocity"); v != o.end() && !(v->is_string() && *v == "extrapolated")) {
    if (!v->is_number()) {
      in.problem(JsonInput::child(where, "velocity"),
                 "expected \"extrapolated\" or a speed in m/s, found " + json_type_name(*v));
      return std::nullopt;
    }
    const double speed = in.number(o, where, "velocity", 0, 0, 1e4, true, "m/s");
    if (!(speed > 0)) return std::nullopt;
    d.speed = speed;
  }
  // The cross-section: the box's extent on the other two axes, in cells about 2 spacings wide
  // (at most 64 a side: a box reaching far beyond the liquid costs nothing more).
  for (int k = 0; k < 2; ++k) {
    const int a = (axis + 1 + k) % 3;
    const double extent = box.max[a] - box.min[a];
    d.across[std::size_t(k)] = a;
    d.lo[std::size_t(k)] = box.min[a];
    d.cells[std::size_t(k)] = int(std::clamp(std::round(extent / (2 * h)), 1.0, 64.0));
    d.cell[std::size_t(k)] = extent / double(d.cells[std::size_t(k)]);
  }
  return d;
}

std::optional<SinkDesc> read_sink(JsonInput& in, const json& s, const std::string& where,
                                  std::size_t index, const SceneDescription& scene) {
  const double h = double(scene.world.spacing);
  in.check_keys(s, where, {"name", "min", "max", "point", "normal", "outflow", "reuse"});
  SinkDesc sink;
  sink.name = in.string(s, where, "name", false).value_or("sink " + std::to_string(index));
  if (s.contains("reuse")) {
    sink.reuse = in.string(s, where, "reuse", true).value_or("");
    const EmitterDesc* emitter = find_emitter(scene, sink.reuse);
    if (!emitter) {
      in.problem(JsonInput::child(where, "reuse"), "no emitter is named '" + sink.reuse + "'");
      return std::nullopt;
    }
    if (emitter->live_limit == std::numeric_limits<std::uint64_t>::max()) {
      in.problem(JsonInput::child(where, "reuse"),
                 "emitter '" + sink.reuse +
                     "' does not reuse particles: give it max_particles and at_limit \"reuse\"");
      return std::nullopt;
    }
  }
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
    if (s.contains("outflow")) {
      sink.outflow = read_outflow(in, s, where, *sink.box, h);
      if (!sink.outflow) return std::nullopt;
    }
    return sink;
  }
  if (s.contains("outflow")) {
    in.problem(JsonInput::child(where, "outflow"),
               "an outflow buffer needs a box sink (\"min\", \"max\"): its face across the "
               "outflow is the outlet");
    return std::nullopt;
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
                                                   const SceneDescription& scene, JsonInput& in) {
  auto data = std::make_shared<SinksData>();
  const bool ok = read_each(node, path, in, "sinks",
                            [&](const json& s, const std::string& where, std::size_t i) {
                              auto sink = read_sink(in, s, where, i, scene);
                              if (sink) data->sinks.push_back(*sink);
                              return sink.has_value();
                            });
  if (!ok) return nullptr;
  return data;
}

void build_sinks(World& world, const SceneDescription&, const SceneSectionData& section) {
  for (const auto& s : static_cast<const SinksData&>(section).sinks) {
    auto sink = std::make_unique<Sink>(s);
    if (!s.reuse.empty())
      for (const auto& source : world.sources())
        if (auto* emitter = dynamic_cast<Emitter*>(source.get());
            emitter && emitter->name() == s.reuse)
          sink->reuse_into(emitter);
    world.add_source(std::move(sink));
  }
}

}  // namespace

SceneSection sinks_scene_section() {
  return {"sinks", "boxes and half-spaces where liquid leaves the scene (docs/emitters.md)",
          read_sinks, build_sinks};
}

}  // namespace upf
