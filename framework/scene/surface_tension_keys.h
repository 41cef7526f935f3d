// The liquid keys of surface tension beside the numeric `surface_tension` (sigma, a parameter of
// the liquid kind): "surface_tension_model", a model's registered name, "adhesion", an object
// of Akinci's adhesion over cohesion ratio beta/gamma toward each named boundary material, and
// "contact_angle", the same wetting asked for as an equilibrium contact angle in degrees per
// boundary material (adhesion_contact_angle.h; docs/surface-tension.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/materials/material.h"
#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/solver/registry.h"

namespace upf {

inline const std::vector<std::string>& surface_tension_keys() {
  static const std::vector<std::string> keys = {"surface_tension_model", "adhesion",
                                                "contact_angle"};
  return keys;
}

// Reads the three keys of liquid material `m` at `path` (the material's JSON path).
void read_surface_tension_keys(JsonInput& in, const nlohmann::json& node, const std::string& path,
                               const Registry& registry, Material& m);

// Once every material is read: adhesion names boundary materials of the scene and comes with a
// surface tension; the liquids one solver moves name one model.
void check_surface_tension_keys(JsonInput& in, const Registry& registry,
                                const SceneDescription& scene);

// The model of `m`: its own, or the registry's first.
std::string surface_tension_model_of(const Material& m, const Registry& registry);

}  // namespace upf
