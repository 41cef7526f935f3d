// Helpers for physics tests: load a shipped sample, adjust it, build and step its world.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

namespace upf::testing {

inline nlohmann::json load_sample_json(const std::string& name) {
  std::ifstream in(std::filesystem::path(UPF_SOURCE_DIR) / "samples" / name);
  return nlohmann::json::parse(in);
}

inline Registry builtin_registry() {
  Registry r;
  register_builtins(r);
  return r;
}

struct TestWorld {
  Registry registry = builtin_registry();
  SceneDescription scene;
  std::unique_ptr<World> world;

  TestWorld(const nlohmann::json& doc, int threads) {
    scene = read_scene(doc, registry, "test");
    world = build_world(scene, registry, threads);
    world->prepare();
  }
  // Steps until time t, landing on it with evenly split steps.
  void run_until(double t) {
    while (world->time() < t - 1e-12) world->step(world->next_time_step_until(t));
  }
};

}  // namespace upf::testing
