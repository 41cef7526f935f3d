#include "framework/scene/scene_reader.h"

#include <unistd.h>
#include <cctype>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "framework/core/file_name.h"
#include "framework/scene/json_input.h"
#include "framework/scene/liquid_mix_keys.h"
#include "framework/scene/periodic_keys.h"
#include "framework/scene/surface_tension_keys.h"
#include "framework/scene/viscosity_keys.h"
#include "framework/scene/world_setting_specs.h"

namespace upf {

namespace {

using nlohmann::json;

// "render" belongs to the pictures (render/): a program that registers its section checks it,
// others (tests, embedders) accept it unread, so one scene file serves them all.
const std::vector<std::string> kTopKeys = {
    "name",       "description",  "gravity", "particle_spacing", "materials",
    "containers", "fluid_blocks", "time",    "output",           "probes",
    "stability",  "neighbours",   "render",  "device",           "periodic"};
const std::vector<std::string> kAxisNames = {"x", "y", "z"};

std::vector<std::string> spec_names(const std::vector<ParamSpec>& specs) {
  std::vector<std::string> names;
  for (const auto& spec : specs) names.push_back(spec.name);
  return names;
}

// The spec a section's reader asks for by name: a missing one is a programming error.
const ParamSpec& spec_named(const std::vector<ParamSpec>& specs, const std::string& name) {
  const ParamSpec* spec = find_spec(specs, name);
  if (!spec) throw std::logic_error("no world-setting spec named '" + name + "'");
  return *spec;
}

std::optional<int> read_axis(JsonInput& in, const json& object, const std::string& path,
                             std::string_view key, std::optional<int> fallback) {
  auto name = in.string(object, path, key, !fallback.has_value());
  if (!name) return fallback;
  for (int a = 0; a < 3; ++a)
    if (*name == kAxisNames[std::size_t(a)]) return a;
  in.problem(JsonInput::child(path, key), "axis '" + *name + "' is not one of x, y, z");
  return std::nullopt;
}

std::optional<Box> read_box(JsonInput& in, const json& object, const std::string& path,
                            double min_extent) {
  auto lo = in.vec3(object, path, "min", true);
  auto hi = in.vec3(object, path, "max", true);
  if (!lo || !hi) return std::nullopt;
  for (int a = 0; a < 3; ++a) {
    if ((*hi)[a] - (*lo)[a] < min_extent || (*hi)[a] < (*lo)[a]) {
      std::ostringstream msg;
      msg << "box is " << (*hi)[a] - (*lo)[a] << " m along " << kAxisNames[std::size_t(a)];
      if (min_extent > 0)
        msg << "; max must exceed min by at least one particle spacing (" << min_extent << " m)";
      else
        msg << "; max must exceed min";
      in.problem(JsonInput::child(path, "max"), msg.str());
      return std::nullopt;
    }
  }
  return Box{*lo, *hi};
}

void read_material(JsonInput& in, const json& node, const std::string& name,
                   const std::string& path, const Registry& registry, SceneDescription& scene) {
  if (!in.expect_object(node, path)) return;
  auto type_name = in.string(node, path, "type", true);
  if (!type_name) return;
  const MaterialKind* kind = registry.find_material_kind(*type_name);
  if (!kind) {
    std::vector<std::string> names;
    for (const auto& k : registry.material_kinds()) names.push_back(k.name);
    std::string msg = "unknown material type '" + *type_name + "'";
    if (auto guess = did_you_mean(*type_name, names)) msg += " (did you mean '" + *guess + "'?)";
    in.problem(JsonInput::child(path, "type"), msg);
    return;
  }
  Material m;
  m.name = name;
  m.kind = kind->name;
  m.type = kind->type;
  m.params = ParamValues(kind->params);
  std::vector<std::string> allowed = {"type", "solver"};
  for (const auto& spec : kind->params) {
    allowed.push_back(spec.name);
    if (!node.contains(spec.name)) continue;
    // Densities and the like must be positive: the spec's range says so.
    auto v =
        in.required_number(node, path, spec.name, spec.min_value, spec.max_value, false, spec.unit);
    if (v && spec.integer && *v != double(std::int64_t(*v))) {
      in.problem(JsonInput::child(path, spec.name), "must be a whole number");
      continue;
    }
    if (v) m.params.set(spec.name, *v);
  }
  if (kind->type == ParticleType::Liquid) {
    allowed.insert(allowed.end(), surface_tension_keys().begin(), surface_tension_keys().end());
    read_surface_tension_keys(in, node, path, registry, m);
  }
  in.check_keys(node, path, allowed);

  // The solver: a name, or an object {"name": ..., parameters...}; the kind's default otherwise.
  std::string solver_name = kind->default_solver;
  const std::string solver_path = JsonInput::child(path, "solver");
  const json* solver_node = nullptr;
  if (auto it = node.find("solver"); it != node.end()) {
    if (it->is_string()) {
      solver_name = it->get<std::string>();
    } else if (it->is_object()) {
      solver_node = &*it;
      auto n = in.string(*it, solver_path, "name", true);
      if (!n) return;
      solver_name = *n;
    } else {
      in.problem(solver_path, "expected a solver name or an object, found " + json_type_name(*it));
      return;
    }
  }
  if (!solver_name.empty()) {
    const SolverInfo* solver = registry.find_solver(solver_name);
    if (!solver || solver->type != kind->type) {
      std::vector<std::string> names;
      for (const auto& s : registry.solvers())
        if (s.type == kind->type) names.push_back(s.name);
      std::string msg = "no solver named '" + solver_name + "' for " + kind->name + " materials";
      if (auto guess = did_you_mean(solver_name, names)) msg += " (did you mean '" + *guess + "'?)";
      in.problem(solver_node ? JsonInput::child(solver_path, "name") : solver_path, msg);
      return;
    }
    m.solver = solver_name;
    m.solver_params = ParamValues(solver->params);
    if (solver_node) {
      std::vector<std::string> solver_keys = {"name"};
      for (const auto& spec : solver->params) {
        solver_keys.push_back(spec.name);
        if (!solver_node->contains(spec.name)) continue;
        auto v = in.required_number(*solver_node, solver_path, spec.name, spec.min_value,
                                    spec.max_value, false, spec.unit);
        if (v && spec.integer && *v != double(std::int64_t(*v))) {
          in.problem(JsonInput::child(solver_path, spec.name), "must be a whole number");
          continue;
        }
        if (v) m.solver_params.set(spec.name, *v);
      }
      in.check_keys(*solver_node, solver_path, solver_keys);
    }
  }
  scene.materials.push_back(std::move(m));
}

// A material reference must name a declared material of the expected type.
bool check_material_ref(JsonInput& in, const SceneDescription& scene, const std::string& name,
                        const std::string& path, ParticleType expected) {
  const Material* m = scene.material(name);
  if (!m && scene.rejected(name)) return false;  // its own problem is reported already
  if (!m) {
    std::vector<std::string> names;
    for (const auto& mat : scene.materials) names.push_back(mat.name);
    std::string msg = "no material named '" + name + "'";
    if (auto guess = did_you_mean(name, names)) msg += " (did you mean '" + *guess + "'?)";
    in.problem(path, msg);
    return false;
  }
  if (m->type != expected) {
    in.problem(path, "material '" + name + "' is " + std::string(to_string(m->type)) +
                         ", expected a " + std::string(to_string(expected)) + " material");
    return false;
  }
  return true;
}

// The probe's "method": one of `allowed` (the first is the default); anything else is an error
// naming the path and the allowed names.
ProbeMethod read_probe_method(JsonInput& in, const json& node, const std::string& path,
                              const std::vector<std::pair<std::string, ProbeMethod>>& allowed) {
  const auto name = in.string(node, path, "method", false);
  if (!name) return allowed.front().second;
  std::vector<std::string> names;
  for (const auto& [known, method] : allowed) {
    if (*name == known) return method;
    names.push_back(known);
  }
  std::string msg = "unknown method '" + *name + "' (allowed: ";
  for (std::size_t i = 0; i < names.size(); ++i) msg += (i ? ", '" : "'") + names[i] + "'";
  in.problem(JsonInput::child(path, "method"), msg + ")");
  return allowed.front().second;
}

void read_probe(JsonInput& in, const json& node, const std::string& path, double spacing,
                SceneDescription& scene) {
  ProbeDesc p;
  auto name = in.string(node, path, "name", true);
  auto type = in.string(node, path, "type", true);
  if (!name || !type) return;
  p.name = *name;
  for (const auto& other : scene.probes)
    if (other.name == p.name) in.problem(JsonInput::child(path, "name"), "duplicate probe name");
  if (*type == "extent") {
    p.kind = ProbeKind::Extent;
    in.check_keys(node, path, {"name", "type", "axis", "side", "region", "surface"});
    p.axis = read_axis(in, node, path, "axis", std::nullopt).value_or(0);
    auto side = in.string(node, path, "side", false).value_or("max");
    if (side != "max" && side != "min")
      in.problem(JsonInput::child(path, "side"), "side '" + side + "' is not 'min' or 'max'");
    p.max_side = side == "max";
    if (auto it = node.find("surface"); it != node.end()) {
      if (it->is_boolean())
        p.surface = it->get<bool>();
      else
        in.problem(JsonInput::child(path, "surface"), "expected true or false");
    }
    if (auto it = node.find("region"); it != node.end()) {
      const std::string rp = JsonInput::child(path, "region");
      if (in.expect_object(*it, rp)) {
        in.check_keys(*it, rp, {"min", "max"});
        p.region = read_box(in, *it, rp, 0.0);
      }
    }
  } else if (*type == "height") {
    p.kind = ProbeKind::Height;
    in.check_keys(node, path, {"name", "type", "axis", "at", "radius", "method"});
    p.axis = read_axis(in, node, path, "axis", 1).value_or(1);
    if (auto at = in.vec2(node, path, "at", true)) p.at = *at;
    p.method = read_probe_method(in, node, path,
                                 {{"top", ProbeMethod::Top}, {"volume", ProbeMethod::Volume}});
    // A wider default for the volume: the kernel's sum over a cubic lattice is within 0.7 % of
    // its integral at 3 s, but only within 4 % at 2 s.
    const double default_radius = (p.method == ProbeMethod::Volume ? 3 : 2) * spacing;
    p.radius = in.number(node, path, "radius", default_radius, 0, 1e6, true, "m");
  } else if (*type == "pressure") {
    p.kind = ProbeKind::Pressure;
    in.check_keys(node, path, {"name", "type", "center", "radius", "method"});
    if (auto c = in.vec3(node, path, "center", true)) p.center = *c;
    p.radius = in.number(node, path, "radius", 2 * spacing, 0, 1e6, true, "m");
    p.method = read_probe_method(in, node, path,
                                 {{"mean", ProbeMethod::Mean}, {"kernel", ProbeMethod::Kernel}});
  } else {
    std::string msg = "unknown probe type '" + *type + "'";
    if (auto guess = did_you_mean(*type, {"extent", "height", "pressure"}))
      msg += " (did you mean '" + *guess + "'?)";
    in.problem(JsonInput::child(path, "type"), msg);
    return;
  }
  scene.probes.push_back(std::move(p));
}

double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kib = 0;
  while (meminfo >> key >> kib) {
    if (key == "MemAvailable:") return kib * 1024.0;
    meminfo.ignore(256, '\n');
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 1e18;
}

// /time, /stability and /neighbours: numbers checked against their specs.
void read_world_settings(JsonInput& in, const json& doc, WorldSettings& w) {
  if (auto it = doc.find("time"); it != doc.end() && in.expect_object(*it, "/time")) {
    const auto specs = time_setting_specs();
    in.check_keys(*it, "/time", spec_names(specs));
    auto& t = w.time;
    t.end = in.number(*it, "/time", spec_named(specs, "end"), t.end);
    t.dt_min = in.number(*it, "/time", spec_named(specs, "dt_min"), t.dt_min);
    t.dt_max = in.number(*it, "/time", spec_named(specs, "dt_max"), t.dt_max);
    t.cfl = in.number(*it, "/time", spec_named(specs, "cfl"), t.cfl);
    t.fixed_dt = in.number(*it, "/time", spec_named(specs, "fixed_dt"), t.fixed_dt);
    if (t.dt_min > t.dt_max) {
      std::ostringstream message;  // %g-like: 1e-300 is not "0.000000"
      message << "dt_min (" << t.dt_min << " s) is larger than dt_max (" << t.dt_max << " s)";
      in.problem("/time/dt_min", message.str());
    }
  }
  if (auto it = doc.find("stability"); it != doc.end() && in.expect_object(*it, "/stability")) {
    const auto specs = stability_setting_specs();
    in.check_keys(*it, "/stability", spec_names(specs));
    w.max_speed = in.number(*it, "/stability", spec_named(specs, "max_speed"), w.max_speed);
  }
  if (auto it = doc.find("neighbours"); it != doc.end() && in.expect_object(*it, "/neighbours")) {
    const auto specs = neighbour_setting_specs();
    in.check_keys(*it, "/neighbours", spec_names(specs));
    w.reorder_every =
        int(in.number(*it, "/neighbours", spec_named(specs, "reorder_every"), w.reorder_every));
  }
}

// /materials, each with its kind's and its solver's parameters.
void read_materials(JsonInput& in, const json& doc, const Registry& registry,
                    SceneDescription& scene) {
  if (auto it = doc.find("materials"); it == doc.end()) {
    in.problem("/materials", "missing (an object of named materials is required)");
  } else if (in.expect_object(*it, "/materials")) {
    for (auto m = it->begin(); m != it->end(); ++m) {
      const std::size_t before = scene.materials.size();
      read_material(in, m.value(), m.key(), JsonInput::child("/materials", m.key()), registry,
                    scene);
      if (scene.materials.size() == before) scene.rejected_materials.push_back(m.key());
    }
  }
  // Materials sharing a solver share one instance: their solver parameters must agree.
  for (std::size_t a = 0; a < scene.materials.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      const auto &ma = scene.materials[a], &mb = scene.materials[b];
      if (!ma.solver.empty() && ma.solver == mb.solver &&
          ma.solver_params.all() != mb.solver_params.all())
        in.problem("/materials/" + ma.name + "/solver",
                   "parameters of solver '" + ma.solver + "' differ from those of material '" +
                       mb.name + "'; materials sharing a solver must share its parameters");
    }
  check_surface_tension_keys(in, registry, scene);
  check_viscosity_keys(in, scene);
  check_liquid_mix_keys(in, registry, scene);
}

// /containers: boxes of frozen wall particles.
void read_containers(JsonInput& in, const json& doc, double h, SceneDescription& scene) {
  in.for_each_object(doc, "", "containers", [&](const json& c, const std::string& path) {
    in.check_keys(c, path, {"material", "min", "max", "layers"});
    ContainerDesc desc;
    auto mat = in.string(c, path, "material", true);
    if (mat && check_material_ref(in, scene, *mat, JsonInput::child(path, "material"),
                                  ParticleType::Frozen))
      desc.material = *mat;
    desc.layers = int(in.number(c, path, "layers", 2, 1, 10));
    auto box = read_box(in, c, path, h);
    if (box) desc.box = *box;
    if (mat && box) scene.containers.push_back(desc);
  });
}

// /fluid_blocks: each must sit inside a container, and no two may overlap: their lattices would
// put particles closer than the spacing, which blow apart at the first steps.
void read_fluid_blocks(JsonInput& in, const json& doc, double h, SceneDescription& scene) {
  std::vector<std::pair<std::string, Box>> earlier;  // every block read so far, with its path
  in.for_each_object(doc, "", "fluid_blocks", [&](const json& b, const std::string& path) {
    in.check_keys(b, path, {"material", "min", "max", "velocity", "shape"});
    FluidBlockDesc desc;
    if (auto shape = in.string(b, path, "shape", false)) {
      desc.ball = *shape == "ball";
      if (*shape != "ball" && *shape != "box")
        in.problem(JsonInput::child(path, "shape"),
                   "unknown shape '" + *shape +
                       "'; allowed: 'box' (the default), 'ball' (the "
                       "ball, or ellipsoid, inscribed in the box)");
    }
    auto mat = in.string(b, path, "material", true);
    const bool mat_ok =
        mat && check_material_ref(in, scene, *mat, JsonInput::child(path, "material"),
                                  ParticleType::Liquid);
    if (mat_ok) desc.material = *mat;
    if (auto v = in.vec3(b, path, "velocity", false)) desc.velocity = *v;
    auto box = read_box(in, b, path, h);
    if (!box) return;
    desc.box = *box;
    for (const auto& [other_path, other] : earlier) {
      const Eigen::Vector3d low = box->min.cwiseMax(other.min);
      const Eigen::Vector3d high = box->max.cwiseMin(other.max);
      if (((high - low).array() > 1e-9 * h).all()) {
        std::ostringstream msg;
        msg << "overlaps " << other_path << " in [" << low.transpose() << "] - ["
            << high.transpose()
            << "]: the two lattices would put particles closer than the spacing; blocks may "
               "touch but not overlap";
        in.problem(path, msg.str());
      }
    }
    earlier.emplace_back(path, *box);
    // A world periodic along every axis needs no walls.
    const auto& periodic = scene.world.periodic.periodic;
    bool inside = periodic[0] && periodic[1] && periodic[2];
    for (const auto& c : scene.containers) inside = inside || c.box.contains(*box, 1e-9);
    if (!inside) {
      std::ostringstream msg;
      msg << "fluid block [" << box->min.transpose() << "] - [" << box->max.transpose()
          << "] is not inside any container";
      in.problem(path, msg.str());
    }
    if (mat_ok) scene.fluid_blocks.push_back(desc);
  });
}

// /output/fields: names only. Which fields exist is known once the solvers have created theirs,
// so the run checks the names (check_output_fields in framework/run).
void read_output_fields(JsonInput& in, const json& f, OutputDesc& output) {
  output.fields.emplace();
  if (!f.is_array()) {
    in.problem("/output/fields", "expected an array of field names");
    return;
  }
  for (std::size_t i = 0; i < f.size(); ++i) {
    const std::string path = JsonInput::child("/output/fields", i);
    const json& name = f[i];
    const bool empty = name.is_string() && name.get<std::string>().empty();
    if (!name.is_string() || empty) {
      in.problem(path, "expected a field name, found " +
                           (empty ? std::string("an empty string") : json_type_name(name)));
      continue;
    }
    output.fields->push_back(name.get<std::string>());
  }
}

// /output/formats: the formats named, and no others.
void read_output_formats(JsonInput& in, const json& f, OutputDesc& output) {
  output.vtp = false;
  if (!f.is_array()) {
    in.problem("/output/formats", "expected an array of format names");
    return;
  }
  // Each format name and the flag it sets; an unknown name gets them all listed.
  const std::pair<const char*, bool OutputDesc::*> known[] = {
      {"vtp", &OutputDesc::vtp},
      {"ply", &OutputDesc::ply},
      {"surface", &OutputDesc::surface},
      {"vdb_points", &OutputDesc::vdb_points},
      {"surface_vdb", &OutputDesc::surface_vdb},
  };
  std::string known_list;
  for (const auto& [format, flag] : known)
    known_list += (known_list.empty() ? "\"" : ", \"") + std::string(format) + "\"";
  for (std::size_t i = 0; i < f.size(); ++i) {
    const json& name = f[i];
    bool found = false;
    for (const auto& [format, flag] : known) {
      if (name.is_string() && name.get<std::string>() == format) {
        output.*flag = true;
        found = true;
      }
    }
    if (!found) {
      in.problem(JsonInput::child("/output/formats", i),
                 "unknown format " + name.dump() + " (known: " + known_list + ")");
    }
  }
}

// A string at object[key] that must be one of `choices`: the index of the one given, or
// `fallback` when absent or wrong (reported).
std::size_t read_choice(JsonInput& in, const json& object, const std::string& path, const char* key,
                        std::initializer_list<const char*> choices, std::size_t fallback) {
  const auto value = in.string(object, path, key, false);
  if (!value) return fallback;
  std::string known;
  std::size_t index = 0;
  for (const char* c : choices) {
    if (*value == c) return index;
    known += (index++ == 0 ? "\"" : ", \"") + std::string(c) + "\"";
  }
  in.problem(JsonInput::child(path, key),
             "unknown value \"" + *value + "\" (allowed: " + known + ")");
  return fallback;
}

// /output/types: {"vtp": ["liquid", ...], "ply": [...], "vdb_points": [...]}, the particle types
// each format writes.
void read_output_types(JsonInput& in, const json& types, OutputDesc& output) {
  const std::string path = "/output/types";
  if (!in.expect_object(types, path)) return;
  in.check_keys(types, path, {"vtp", "ply", "vdb_points"});
  for (auto [format, mask] :
       {std::pair{"vtp", &OutputDesc::vtp_types}, std::pair{"ply", &OutputDesc::ply_types},
        std::pair{"vdb_points", &OutputDesc::vdb_points_types}}) {
    auto it = types.find(format);
    if (it == types.end()) continue;
    const std::string where = JsonInput::child(path, format);
    if (!it->is_array()) {
      in.problem(where, "expected an array of particle types, found " + json_type_name(*it));
      continue;
    }
    TypeMask chosen = 0;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& name = (*it)[i];
      const auto type =
          name.is_string() ? parse_particle_type(name.get<std::string>()) : std::nullopt;
      if (!type) {
        std::string known;  // from the enum's own names, so a fifth type is listed too
        for (int t = 0; t < kParticleTypeCount; ++t)
          known += (t == 0 ? "\"" : ", \"") + std::string(to_string(static_cast<ParticleType>(t))) +
                   "\"";
        in.problem(JsonInput::child(where, i),
                   "unknown particle type " + name.dump() + " (known: " + known + ")");
        continue;
      }
      chosen |= mask_of(*type);
    }
    output.*mask = chosen;
  }
}

// /output: frame rate, field names, formats and how the files are laid out.
void read_output(JsonInput& in, const json& doc, SceneDescription& scene) {
  auto it = doc.find("output");
  if (it == doc.end() || !in.expect_object(*it, "/output")) return;
  const auto specs = output_setting_specs();
  std::vector<std::string> keys = spec_names(specs);
  keys.insert(keys.end(), {"fields", "formats", "compression", "frozen", "types", "ply_up",
                           "pieces", "vdb_compression", "surface_method"});
  in.check_keys(*it, "/output", keys);
  OutputDesc& output = scene.output;
  output.fps = in.number(*it, "/output", spec_named(specs, "fps"), output.fps);
  output.size_warning_gb =
      in.number(*it, "/output", spec_named(specs, "size_warning"), output.size_warning_gb);
  output.probe_every =
      int(in.number(*it, "/output", spec_named(specs, "probe_every"), output.probe_every));
  output.surface_voxel =
      in.number(*it, "/output", spec_named(specs, "surface_voxel"), output.surface_voxel);
  output.surface_memory_gb =
      in.number(*it, "/output", spec_named(specs, "surface_memory"), output.surface_memory_gb);
  if (auto f = it->find("fields"); f != it->end()) read_output_fields(in, *f, output);
  if (auto f = it->find("formats"); f != it->end()) read_output_formats(in, *f, output);
  output.compress = read_choice(in, *it, "/output", "compression", {"zlib", "none"},
                                output.compress ? 0 : 1) == 0;
  output.frozen_once = read_choice(in, *it, "/output", "frozen", {"once", "every_frame"},
                                   output.frozen_once ? 0 : 1) == 0;
  output.ply_z_up =
      read_choice(in, *it, "/output", "ply_up", {"y", "z"}, output.ply_z_up ? 1 : 0) == 1;
  output.pieces_per_rank = read_choice(in, *it, "/output", "pieces", {"gathered", "per_rank"},
                                       output.pieces_per_rank ? 1 : 0) == 1;
  if (auto f = it->find("types"); f != it->end()) read_output_types(in, *f, output);
  static constexpr const char* kVdbCompressions[] = {"none", "truncate", "fixed_point"};
  output.vdb_compression = kVdbCompressions[read_choice(in, *it, "/output", "vdb_compression",
                                                        {"none", "truncate", "fixed_point"}, 0)];
  static constexpr const char* kSurfaceMethods[] = {"anisotropic", "spheres"};
  output.surface_method = kSurfaceMethods[read_choice(in, *it, "/output", "surface_method",
                                                      {"anisotropic", "spheres"}, 0)];
}

// Plug-in sections ("bodies"), once materials, spacing and containers are known; something must
// move: liquid, or what a plug-in section adds (grains, bodies).
void read_sections(JsonInput& in, const json& doc, const Registry& registry,
                   SceneDescription& scene) {
  for (const auto& section : registry.scene_sections()) {
    auto it = doc.find(section.key);
    if (it == doc.end()) continue;
    auto data = section.read(*it, "/" + section.key, scene, in);
    if (data) scene.sections.push_back({section.key, std::move(data)});
  }
  bool moving_sections = false;
  for (const auto& section : scene.sections)
    moving_sections = moving_sections || section.data->moves();
  if (scene.fluid_blocks.empty() && !moving_sections && in.clean())
    in.problem("/fluid_blocks", "the scene has no fluid block: nothing would move");
}

// Memory: estimated before anything is allocated.
void check_memory(JsonInput& in, const SceneDescription& scene) {
  const double particles = scene.estimated_particles();
  const double needed = particles * kEstimatedBytesPerParticle;
  const double available = available_memory_bytes();
  if (particles > 4.0e9 || needed > available) {
    std::ostringstream msg;
    msg << "the scene would create about " << particles << " particles, needing about "
        << needed / double(1 << 30) << " GiB; this machine has " << available / double(1 << 30)
        << " GiB available. Increase the spacing or shrink the blocks";
    in.problem("/particle_spacing", msg.str());
  }
}

}  // namespace

SceneDescription read_scene(const json& doc, const Registry& registry, const std::string& source) {
  std::vector<InputProblem> problems;
  JsonInput in(problems);
  SceneDescription scene;
  scene.source = source;
  auto fail_if_any = [&] {
    if (problems.empty()) return;
    for (auto& p : problems) p.where = source + ":" + (p.where.empty() ? "/" : p.where);
    throw InputError(std::move(problems));
  };
  if (!in.expect_object(doc, "")) fail_if_any();
  std::vector<std::string> top_keys = kTopKeys;
  for (const auto& section : registry.scene_sections()) top_keys.push_back(section.key);
  in.check_keys(doc, "", top_keys);

  scene.name =
      in.string(doc, "", "name", false).value_or(std::filesystem::path(source).stem().string());
  // The name becomes the default output folder, out/<name>: one plain name, never a path.
  if (auto bad = file_name_problem(scene.name))
    in.problem("/name", "'" + scene.name + "' " + *bad +
                            ": the name becomes the output folder out/<name>, so it must be one "
                            "plain name (no '/', '\\', '..', control characters or leading '-')");
  in.string(doc, "", "description", false);
  // Checked against the devices of the build when a run makes it (device/device_pipelines.h).
  scene.device = in.string(doc, "", "device", false).value_or("cpu");
  if (auto g = in.vec3(doc, "", "gravity", false)) {
    scene.world.gravity = {Real((*g)[0]), Real((*g)[1]), Real((*g)[2])};
  }
  const auto spacing = in.required_number(doc, "", "particle_spacing", 0, 100, true, "m");
  if (spacing) scene.world.spacing = Real(*spacing);
  // An unusable spacing is reported once: the extents of boxes are then not measured in it.
  const double h = spacing.value_or(0.0);

  read_world_settings(in, doc, scene.world);
  const PeriodicBounds periodic = read_periodic(in, doc, scene);
  read_materials(in, doc, registry, scene);
  read_containers(in, doc, h, scene);
  read_fluid_blocks(in, doc, h, scene);
  read_output(in, doc, scene);
  read_sections(in, doc, registry, scene);
  check_periodic_scene(in, periodic, scene);
  in.for_each_object(doc, "", "probes", [&](const json& probe, const std::string& path) {
    read_probe(in, probe, path, h, scene);
  });
  if (in.clean()) check_memory(in, scene);
  fail_if_any();
  return scene;
}

namespace {
// "file:line:column" of byte `offset` (0-based) of `text`.
std::string place_in(const std::filesystem::path& path, const std::string& text,
                     std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return path.string() + ":" + std::to_string(line) + ":" + std::to_string(column);
}

// The first place where `number` stands as a whole JSON number token, else the text's end.
std::size_t find_number(const std::string& text, const std::string& number) {
  auto is_number_char = [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
           c == '+' || c == '-';
  };
  for (std::size_t at = text.find(number); at != std::string::npos;
       at = text.find(number, at + 1)) {
    const bool starts = at == 0 || !is_number_char(text[at - 1]);
    const std::size_t end = at + number.size();
    if (starts && (end == text.size() || !is_number_char(text[end]))) return at;
  }
  return text.size();
}
}  // namespace

nlohmann::json read_scene_json(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) {
    throw InputError(path.string(), std::filesystem::exists(path) ? "cannot be read (permissions?)"
                                                                  : "no such file");
  }
  std::stringstream buffer;
  buffer << file.rdbuf();
  const std::string text = buffer.str();
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    // The byte offset as a line and column the user can find (e.byte is 1-based).
    throw InputError(place_in(path, text, e.byte == 0 ? 0 : e.byte - 1),
                     std::string("invalid JSON: ") + e.what());
  } catch (const json::out_of_range& e) {
    // A number beyond a double (1e400): the parser names the token but not where it stands.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    const std::string number =
        open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    throw InputError(place_in(path, text, number.empty() ? 0 : find_number(text, number)),
                     "the number " + (number.empty() ? std::string("here") : number) +
                         " is out of range: a double holds magnitudes up to about 1.8e308");
  }
  return doc;
}

SceneDescription load_scene_file(const std::filesystem::path& path, const Registry& registry) {
  return read_scene(read_scene_json(path), registry, path.string());
}

}  // namespace upf
