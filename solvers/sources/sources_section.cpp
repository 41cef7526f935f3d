#include "solvers/sources/sources_section.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "framework/core/vec3_eigen.h"
#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/solver/registry.h"
#include "framework/world/world.h"
#include "solvers/sources/emitter.h"
#include "solvers/sources/json_array.h"

namespace upf {

namespace {

using nlohmann::json;

// An emitter as read: what its source needs, and its nozzle's walls.
struct EmitterEntry {
  EmitterDesc desc;
  MaterialId nozzle_material = 0;
  std::vector<Eigen::Vector3d> nozzle;  // positions of the nozzle's frozen particles
};

struct EmittersData : SceneSectionData {
  std::vector<EmitterEntry> emitters;
  double end_time = 0;  // the scene's /time/end
  // The nozzles' walls and the liquid poured by the scene's end: the memory check refuses a
  // pour that would not fit before anything is written.
  double estimated_particles() const override {
    double n = 0;
    for (const auto& e : emitters)
      n += double(e.nozzle.size()) +
           std::min(particles_due(e.desc, e.desc.speed.distance(0, end_time)),
                    double(e.desc.live_limit));
    return n;
  }
  bool moves() const override { return !emitters.empty(); }
};

// The material named at object[key], if it exists and has particles of `type`; else a problem.
std::optional<MaterialId> material_of(JsonInput& in, const json& object, const std::string& path,
                                      const char* key, const SceneDescription& scene,
                                      ParticleType type, bool required) {
  const auto name = in.string(object, path, key, required);
  if (!name) return std::nullopt;
  const std::string where = JsonInput::child(path, key);
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == *name) {
      if (scene.materials[m].type == type) return MaterialId(m);
      in.problem(where, "material '" + *name + "' is " +
                            std::string(to_string(scene.materials[m].type)) + "; it must be " +
                            std::string(to_string(type)));
      return std::nullopt;
    }
  if (!scene.rejected(*name)) in.problem(where, "unknown material '" + *name + "'");
  return std::nullopt;
}

// Two unit vectors spanning the plane normal to `d`: `width` (projected) first when given.
std::pair<Eigen::Vector3d, Eigen::Vector3d> plane_axes(
    const Eigen::Vector3d& d, const std::optional<Eigen::Vector3d>& width) {
  Eigen::Vector3d seed;
  if (width && (*width - width->dot(d) * d).norm() > 1e-6 * width->norm()) {
    seed = *width;
  } else {
    int least = 0;  // the world axis least aligned with d
    for (int a = 1; a < 3; ++a)
      if (std::abs(d[a]) < std::abs(d[least])) least = a;
    seed = Eigen::Vector3d::Unit(least);
  }
  const Eigen::Vector3d e1 = (seed - seed.dot(d) * d).normalized();
  return {e1, d.cross(e1)};
}

// The speed: a number, or keyframes [[t, v], ...] with increasing times.
std::optional<std::vector<std::pair<double, double>>> read_speed(JsonInput& in, const json& e,
                                                                 const std::string& path) {
  const std::string where = JsonInput::child(path, "speed");
  auto it = e.find("speed");
  if (it == e.end()) {
    in.problem(where, "missing: a speed in m/s (a number, or keyframes [[t, v], ...])");
    return std::nullopt;
  }
  if (it->is_number()) {
    const double v = in.number(e, path, "speed", 0, 0, 1e4, true, "m/s");
    if (!(v > 0)) return std::nullopt;
    return std::vector<std::pair<double, double>>{{0.0, v}};
  }
  std::vector<std::pair<double, double>> keys;
  bool ok = it->is_array() && !it->empty();
  for (std::size_t k = 0; ok && k < it->size(); ++k) {
    const json& key = (*it)[k];
    ok = key.is_array() && key.size() == 2 && key[0].is_number() && key[1].is_number();
    if (!ok) break;
    const double t = key[0].get<double>(), v = key[1].get<double>();
    if (!std::isfinite(t) || !std::isfinite(v) || v < 0 || v > 1e4 ||
        (!keys.empty() && !(t > keys.back().first))) {
      in.problem(JsonInput::child(where, k),
                 "a keyframe [t, v] needs increasing finite times and a speed in [0, 1e4] m/s");
      return std::nullopt;
    }
    keys.emplace_back(t, v);
  }
  if (!ok) {
    in.problem(where,
               "expected a speed in m/s or keyframes [[t, v], ...], found " + json_type_name(*it));
    return std::nullopt;
  }
  bool flows = false;
  for (const auto& [t, v] : keys) flows = flows || v > 0;
  if (!flows) {
    in.problem(where, "every keyframe's speed is 0: the emitter would never emit");
    return std::nullopt;
  }
  return keys;
}

// The inner box of a container that holds `x`, if any.
const ContainerDesc* container_holding(const SceneDescription& scene, const Eigen::Vector3d& x) {
  for (const auto& c : scene.containers)
    if ((x.array() > c.box.min.array()).all() && (x.array() < c.box.max.array()).all()) return &c;
  return nullptr;
}

std::string text_of(const Eigen::Vector3d& x) {
  std::ostringstream out;
  out << "[" << x.x() << ", " << x.y() << ", " << x.z() << "]";
  return out.str();
}

// "max_particles" and "at_limit": the most particles the emitter may add (whole layers). With
// "close" it stops there, as SPlisHSPlasH's emitters do; with "error" (the default) a pour that
// would pass it by /time/end is refused here, and one that passes it later (a longer --end)
// stops the run there with the frames kept; with "reuse" it is the most of its particles in the
// scene at once, and sinks that reuse into it give back room (SPlisHSPlasH's particle reuse).
void read_particle_budget(JsonInput& in, const json& e, const std::string& path,
                          const SceneDescription& scene, EmitterDesc& d) {
  const double end_time = scene.world.time.end;
  const std::string where = JsonInput::child(path, "max_particles");
  if (!e.contains("max_particles")) {
    if (e.contains("at_limit"))
      in.problem(JsonInput::child(path, "at_limit"), "at_limit needs max_particles");
    return;
  }
  const double most = in.number(e, path, "max_particles", 1, 1, 4.0e9);
  const std::string at_limit = in.string(e, path, "at_limit", false).value_or("error");
  const double per_layer = double(d.opening.size());
  const auto layers = std::uint64_t(std::floor(most / per_layer));
  if (layers == 0) {
    in.problem(where, "max_particles " + std::to_string(std::uint64_t(most)) +
                          " is less than one layer of this opening (" +
                          std::to_string(d.opening.size()) + " particles)");
    return;
  }
  if (at_limit == "close") {
    d.max_layers = std::min(d.max_layers, layers);
  } else if (at_limit == "reuse") {
    d.live_limit = std::uint64_t(most);
  } else if (at_limit == "error") {
    d.budget_layers = layers;
    d.budget_where = scene.source.string() + ":" + where;
    const double poured =
        std::min(std::floor(d.speed.distance(0, end_time) / d.spacing) + 1, double(d.max_layers));
    if (poured > double(layers))
      in.problem(where, "the pour until /time/end (" + std::to_string(end_time) + " s) adds " +
                            std::to_string(std::uint64_t(poured * per_layer)) +
                            " particles, more than max_particles " +
                            std::to_string(std::uint64_t(most)) +
                            ": raise it, pour less (end, volume), or set at_limit \"close\" to "
                            "stop the emitter at the limit");
  } else {
    in.problem(JsonInput::child(path, "at_limit"),
               "unknown at_limit '" + at_limit + "' (allowed: \"error\", \"close\", \"reuse\")");
  }
}

// "profile": the velocity profile across the opening (inflow_profile.h), after the lattice.
bool read_inflow_profile(JsonInput& in, const json& e, const std::string& path,
                         const SceneDescription& scene, EmitterDesc& d) {
  const std::string name = in.string(e, path, "profile", false).value_or("uniform");
  const std::string where = JsonInput::child(path, "profile");
  InflowProfileKind kind{};
  if (!parse_inflow_profile(name, kind)) {
    in.problem(where, "unknown profile '" + name +
                          "' (allowed: \"uniform\", \"parabolic\", \"open_channel\")");
    return false;
  }
  // open_channel's bed is the opening's edge lowest along gravity.
  const Vec3 g = scene.world.gravity;
  const Eigen::Vector3d down(double(g.x), double(g.y), double(g.z));
  const Eigen::Vector3d across = -(down - down.dot(d.direction) * d.direction);
  if (kind == InflowProfileKind::OpenChannel && !(across.norm() > 1e-6 * down.norm())) {
    in.problem(where,
               "an open_channel profile needs gravity across the flow (its bed is the opening's "
               "lowest edge): gravity is zero or along the emitter's direction");
    return false;
  }
  const Eigen::Vector3d up =
      kind == InflowProfileKind::OpenChannel ? across.normalized() : Eigen::Vector3d(d.height);
  d.profile = InflowProfile(kind, d.opening, d.width, d.height, d.circle, d.spacing, up);
  return true;
}

std::optional<EmitterEntry> read_emitter(JsonInput& in, const json& e, const std::string& path,
                                         std::size_t index, const SceneDescription& scene) {
  in.check_keys(
      e, path,
      {"name", "material", "shape", "center", "direction", "radius", "size", "width_axis", "speed",
       "profile", "start", "end", "volume", "nozzle", "buffer", "max_particles", "at_limit"});
  const double h = double(scene.world.spacing);
  EmitterEntry entry;
  EmitterDesc& d = entry.desc;
  d.name = in.string(e, path, "name", false).value_or("emitter " + std::to_string(index));
  d.spacing = h;
  const auto material = material_of(in, e, path, "material", scene, ParticleType::Liquid, true);
  const auto center = in.vec3(e, path, "center", true);
  const auto direction = in.vec3(e, path, "direction", true);
  const auto speed = read_speed(in, e, path);
  const double start = in.number(e, path, "start", 0, 0, 1e7, false, "s");
  const double end = in.number(e, path, "end", 1e7, 0, 1e7, false, "s");
  if (end <= start) in.problem(JsonInput::child(path, "end"), "the end must come after the start");
  const std::string shape = in.string(e, path, "shape", false).value_or("circle");
  if (direction && !(direction->norm() > 0))
    in.problem(JsonInput::child(path, "direction"), "the direction must not be zero");
  if (!material || !center || !direction || !speed || !(direction->norm() > 0) || end <= start)
    return std::nullopt;
  const Material& mat = scene.materials[*material];
  d.material = *material;
  d.particle_mass = Real(mat.param("density") * h * h * h);
  d.center = *center;
  d.direction = direction->normalized();
  d.speed = SpeedProfile(*speed, start, end);

  // The opening's lattice, and the nozzle's rings around it (`layers` wide).
  const auto width_axis = in.vec3(e, path, "width_axis", false);
  const auto [e1, e2] = plane_axes(d.direction, width_axis);
  d.width = e1;
  d.height = e2;
  d.buffer = in.number(e, path, "buffer", 2, 0, 100, false) * h;
  std::function<bool(double, double, double)> inside;  // (u, v, grown by) -> in the shape
  double reach = 0;                                    // largest |u|, |v| of the shape
  double su = 0, sv = 0;  // the lattice's offset from the centre, in spacings
  if (shape == "circle") {
    const double r = in.number(e, path, "radius", 0, 0, 1e3, true, "m");
    if (!(r > 0)) return std::nullopt;
    inside = [r](double u, double v, double grow) {
      return u * u + v * v <= (r + grow) * (r + grow) * (1 + 1e-12);
    };
    reach = r;
    d.circle = true;
    d.radius = r;
  } else if (shape == "rectangle") {
    const auto size = in.vec2(e, path, "size", true);
    if (!size) return std::nullopt;
    if (!((*size).array() > 0).all() || !((*size).array() < 1e3).all()) {
      in.problem(JsonInput::child(path, "size"), "width and height must be in (0, 1e3) m");
      return std::nullopt;
    }
    // Points per side: the lattice nearest the size (at least one), centred on `center`.
    const double nu = std::max(1.0, std::round((*size)[0] / h));
    const double nv = std::max(1.0, std::round((*size)[1] / h));
    // An even count of points per side sits half a spacing off the centre.
    su = std::fmod(nu, 2.0) == 0 ? 0.5 : 0.0;
    sv = std::fmod(nv, 2.0) == 0 ? 0.5 : 0.0;
    inside = [nu, nv, h](double u, double v, double grow) {
      return std::abs(u) <= 0.5 * (nu - 1) * h + grow + 1e-9 * h &&
             std::abs(v) <= 0.5 * (nv - 1) * h + grow + 1e-9 * h;
    };
    reach = 0.5 * std::max(nu, nv) * h;
    d.circle = false;
    d.half_width = 0.5 * (nu - 1) * h;
    d.half_height = 0.5 * (nv - 1) * h;
  } else {
    in.problem(JsonInput::child(path, "shape"),
               "unknown shape '" + shape + "' (allowed: 'circle', 'rectangle')");
    return std::nullopt;
  }
  if (reach / h > 2000) {
    in.problem(path, "the opening is more than 2000 spacings across");
    return std::nullopt;
  }
  int layers = 2, length = 3;
  if (auto it = e.find("nozzle"); it != e.end()) {
    if (it->is_boolean()) {
      if (!it->get<bool>()) layers = 0;
    } else if (in.expect_object(*it, JsonInput::child(path, "nozzle"))) {
      const std::string where = JsonInput::child(path, "nozzle");
      in.check_keys(*it, where, {"layers", "length", "material"});
      layers = int(in.number(*it, where, "layers", 2, 1, 5));
      length = int(in.number(*it, where, "length", 3, 1, 50));
    }
  }
  std::optional<MaterialId> nozzle_material;
  if (layers > 0) {
    const json nozzle = e.value("nozzle", json::object());
    if (nozzle.is_object() && nozzle.contains("material")) {
      nozzle_material = material_of(in, nozzle, JsonInput::child(path, "nozzle"), "material", scene,
                                    ParticleType::Frozen, true);
    } else {
      for (std::size_t m = 0; m < scene.materials.size() && !nozzle_material; ++m)
        if (scene.materials[m].type == ParticleType::Frozen) nozzle_material = MaterialId(m);
      if (!nozzle_material)
        in.problem(JsonInput::child(path, "nozzle"),
                   "the nozzle's walls need a frozen material and the scene has none: add one, or "
                   "set \"nozzle\": false");
    }
    if (!nozzle_material) return std::nullopt;
    entry.nozzle_material = *nozzle_material;
  }
  const long long n = (long long)std::ceil(reach / h) + layers + 1;
  for (long long j = -n; j <= n; ++j)
    for (long long i = -n; i <= n; ++i) {
      const double u = (double(i) + su) * h, v = (double(j) + sv) * h;
      const Eigen::Vector3d offset = u * e1 + v * e2;
      if (inside(u, v, 0)) {
        d.opening.push_back(offset);
      } else if (layers > 0 && inside(u, v, double(layers) * h)) {
        for (int k = 0; k < length; ++k)
          entry.nozzle.push_back(d.center + offset - double(k) * h * d.direction);
      }
    }
  if (d.opening.empty()) {
    in.problem(path, "the opening holds no lattice point at this particle spacing: make it wider");
    return std::nullopt;
  }
  if (!read_inflow_profile(in, e, path, scene, d)) return std::nullopt;
  if (auto volume = e.find("volume"); volume != e.end()) {
    const double v = in.number(e, path, "volume", 0, 0, 1e9, true, "m^3");
    if (v > 0)
      d.max_layers = std::uint64_t(std::ceil(v / (double(d.opening.size()) * h * h * h) - 1e-9));
  }
  read_particle_budget(in, e, path, scene, d);
  // Where the liquid goes in: inside a container, clear of its walls and of the fluid blocks.
  const Eigen::Vector3d ahead = d.center + 2 * h * d.direction;
  if (!container_holding(scene, d.center)) {
    in.problem(JsonInput::child(path, "center"), "the opening " + text_of(d.center) +
                                                     " is not inside any container (inside a "
                                                     "wall, or outside the scene)");
    return std::nullopt;
  }
  if (!container_holding(scene, ahead)) {
    in.problem(JsonInput::child(path, "direction"),
               "the emitter points into a wall: two spacings ahead of the opening, " +
                   text_of(ahead) + ", is outside the container");
    return std::nullopt;
  }
  for (std::size_t b = 0; b < scene.fluid_blocks.size(); ++b) {
    const Box& box = scene.fluid_blocks[b].box;
    for (const auto& o : d.opening)
      for (const Eigen::Vector3d& x : {Eigen::Vector3d(d.center + o), Eigen::Vector3d(ahead + o)})
        if ((x.array() > box.min.array() - 0.5 * h).all() &&
            (x.array() < box.max.array() + 0.5 * h).all()) {
          in.problem(path, "the emitter's first layers overlap the liquid of fluid block " +
                               std::to_string(b) + " at " + text_of(x));
          return std::nullopt;
        }
  }
  return entry;
}

std::shared_ptr<const SceneSectionData> read_emitters(const json& node, const std::string& path,
                                                      const SceneDescription& scene,
                                                      JsonInput& in) {
  if (!(scene.world.spacing > 0)) return nullptr;  // reported at /particle_spacing
  auto data = std::make_shared<EmittersData>();
  data->end_time = scene.world.time.end;
  const bool ok = read_each(
      node, path, in, "emitters", [&](const json& e, const std::string& where, std::size_t i) {
        auto entry = read_emitter(in, e, where, i, scene);
        if (!entry) return false;
        for (const auto& other : data->emitters)
          if (other.desc.name == entry->desc.name)
            in.problem(JsonInput::child(where, "name"),
                       "another emitter has the name '" + entry->desc.name + "'");
        data->emitters.push_back(std::move(*entry));
        return true;
      });
  if (!ok) return nullptr;
  return data;
}

}  // namespace

const EmitterDesc* find_emitter(const SceneDescription& scene, const std::string& name) {
  for (const auto& section : scene.sections)
    if (section.key == "emitters" && section.data)
      for (const auto& e : static_cast<const EmittersData&>(*section.data).emitters)
        if (e.desc.name == name) return &e.desc;
  return nullptr;
}

namespace {

void build_emitters(World& world, const SceneDescription&, const SceneSectionData& section) {
  const auto& data = static_cast<const EmittersData&>(section);
  Particles& p = world.particles();
  for (const auto& e : data.emitters) {
    for (const auto& x : e.nozzle)
      p.add(to_vec3(x), Vec3{}, Real(0), ParticleType::Frozen, e.nozzle_material);
    world.add_source(std::make_unique<Emitter>(e.desc));
  }
}

}  // namespace

SceneSection emitters_scene_section() {
  return {
      "emitters",
      "nozzles that pour liquid in, layer by layer at the particle spacing, at a speed that may "
      "follow keyframes (docs/emitters.md)",
      read_emitters, build_emitters};
}

void register_sources(Registry& registry) {
  registry.add_scene_section(emitters_scene_section());
  registry.add_scene_section(sinks_scene_section());
}

}  // namespace upf
