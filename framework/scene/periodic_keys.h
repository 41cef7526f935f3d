// The scene's "/periodic" key: the axes along which the world repeats (periodic_box.h), as
// {"x": [lo, hi], "z": [lo, hi]}, and what a periodic scene must satisfy (docs/periodic.md).
#pragma once

#include <array>

#include <nlohmann/json.hpp>

#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"

namespace upf {

// The periodic intervals as the scene gives them (scene.world.periodic holds them in Real).
struct PeriodicBounds {
  std::array<bool, 3> periodic{false, false, false};
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
};

// Reads /periodic into scene.world.periodic, after the world settings: each period must exceed
// two support radii (no particle meets its own image) and be a whole number of particle
// spacings (the lattices of blocks and walls tile across the faces).
PeriodicBounds read_periodic(JsonInput& in, const nlohmann::json& doc, SceneDescription& scene);

// Once the materials, containers, fluid blocks and sections are read: containers span the period
// along a periodic axis (their walls there are left out), fluid blocks lie inside it, and grains
// and bodies are refused (not built for periodic domains yet).
void check_periodic_scene(JsonInput& in, const PeriodicBounds& bounds,
                          const SceneDescription& scene);

}  // namespace upf
