// A test world whose registry holds the built-ins and PBF, as the `upf` program's does.
#pragma once

#include <string>

#include "register_pbf.h"
#include "tests/physics/scene_helpers.h"

namespace upf::pbf::testing {

inline Registry pbf_registry() {
  Registry registry = upf::testing::builtin_registry();
  register_pbf(registry);
  return registry;
}

// A shipped sample (samples/NAME) with the liquid "water" moved by PBF with these parameters.
inline nlohmann::json with_pbf(const std::string& sample,
                               nlohmann::json solver = nlohmann::json::object()) {
  auto doc = upf::testing::load_sample_json(sample);
  solver["name"] = "pbf";
  doc["materials"]["water"]["solver"] = solver;
  return doc;
}

inline upf::testing::TestWorld pbf_world(const nlohmann::json& doc, int threads) {
  return upf::testing::TestWorld(doc, threads, pbf_registry());
}

}  // namespace upf::pbf::testing
