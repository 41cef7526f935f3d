// Helpers for physics tests: load a shipped sample, adjust it, build and step its world.
#pragma once

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "coupling/bodies/bodies_section.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

namespace upf::testing {

inline nlohmann::json load_sample_json(const std::string& name) {
  std::ifstream in(std::filesystem::path(UPF_SOURCE_DIR) / "samples" / name);
  return nlohmann::json::parse(in);
}

// Whether x stands at least `margin` inside a square tank's side walls (x and z in [0, width]): the
// interior columns where a tank's pressure is read away from the walls' kernel deficit.
inline bool in_interior_columns(const Vec3& x, double width, double margin) {
  return x.x >= margin && x.x <= width - margin && x.z >= margin && x.z <= width - margin;
}

// Two liquids moved by one `solver` (both with its parameters), and frozen "walls": the materials
// of the multi-liquid test scenes. PCISPH, DFSPH and IISPH at eta 0.5 %.
inline nlohmann::json two_liquid_materials(const std::string& solver, const std::string& first,
                                           double first_density, const std::string& second,
                                           double second_density, bool wall_pressure,
                                           double viscosity = 1e-3) {
  nlohmann::json solver_json = {{"name", solver}};
  if (wall_pressure) solver_json["wall_pressure"] = 1;
  if (solver != "wcsph") solver_json["eta"] = 0.005;
  auto liquid = [&](double density) {
    return nlohmann::json{{"type", "liquid"},
                          {"density", density},
                          {"viscosity", viscosity},
                          {"solver", solver_json}};
  };
  return {{first, liquid(first_density)},
          {second, liquid(second_density)},
          {"walls", {{"type", "frozen"}}}};
}

// The dam break at 4 cm with its column split in two liquids: water below, oil (800) above, both
// moved by `solver` (solvers/fluid/density_contrast.h); with the wall pressure where asked.
inline nlohmann::json oil_on_water_dam_break(const std::string& solver,
                                             bool wall_pressure = false) {
  auto doc = load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  nlohmann::json solver_json = {{"name", solver}};
  if (wall_pressure) solver_json["wall_pressure"] = 1;
  doc["materials"]["water"]["solver"] = solver_json;
  doc["materials"]["oil"] = {
      {"type", "liquid"}, {"density", 800}, {"viscosity", 0.001}, {"solver", solver_json}};
  doc["fluid_blocks"] = {{{"material", "water"}, {"min", {0, 0, 0}}, {"max", {0.6, 0.4, 0.4}}},
                         {{"material", "oil"}, {"min", {0, 0.4, 0}}, {"max", {0.6, 0.8, 0.4}}}};
  return doc;
}

// The dam break at 4 cm in a channel that repeats along x (docs/periodic.md): a row of columns
// 1.6 m apart, each collapsing both ways, its surge leaving through x = 0 coming back in below
// x = 1.6.
inline nlohmann::json periodic_dam_break(const std::string& solver = "pcisph") {
  auto doc = load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  doc["materials"]["water"]["solver"] = {{"name", solver}};
  doc["periodic"] = {{"x", {0, 1.6}}};
  doc.erase("probes");
  return doc;
}

inline Registry builtin_registry() {
  Registry r;
  register_builtins(r);
  return r;
}

// The built-ins plus the "bodies" scene section of coupling/.
inline Registry coupled_registry() {
  Registry r = builtin_registry();
  register_coupling(r);
  return r;
}

struct TestWorld {
  Registry registry = coupled_registry();
  SceneDescription scene;
  std::unique_ptr<World> world;

  TestWorld(const nlohmann::json& doc, int threads) { start(doc, threads); }
  // With another registry: the built-ins plus an extension's solvers, say.
  TestWorld(const nlohmann::json& doc, int threads, Registry with) : registry(std::move(with)) {
    start(doc, threads);
  }
  // Built but not prepared: the test edits particles, then calls world->prepare().
  struct Unprepared {};
  TestWorld(const nlohmann::json& doc, int threads, Unprepared) { start(doc, threads, false); }
  void start(const nlohmann::json& doc, int threads, bool prepare = true) {
    scene = read_scene(doc, registry, "test");
    world = build_world(scene, registry, threads);
    if (prepare) world->prepare();
  }
  // Steps until time t, landing on it with evenly split steps.
  void run_until(double t) {
    while (world->time() < t - 1e-12) world->step(world->next_time_step_until(t));
  }
};

// Positions and velocities by stable id: states compared across thread counts or orderings.
using StateById = std::map<ParticleId, std::pair<Vec3, Vec3>>;

inline StateById state_by_id(const Particles& p) {
  StateById state;
  for (std::size_t i = 0; i < p.size(); ++i) state[p.id[i]] = {p.position[i], p.velocity[i]};
  return state;
}

inline bool bitwise_equal(const Vec3& a, const Vec3& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// How many particles of `a` differ from `b` in some bit of position or velocity; with
// `positions_only`, of position (a run against its start: how many moved).
inline std::size_t bitwise_differences(const StateById& a, const StateById& b,
                                       bool positions_only = false) {
  std::size_t differing = 0;
  for (const auto& [id, s] : a) {
    const auto& t = b.at(id);
    const bool same =
        bitwise_equal(s.first, t.first) && (positions_only || bitwise_equal(s.second, t.second));
    differing += same ? 0 : 1;
  }
  return differing;
}

}  // namespace upf::testing
