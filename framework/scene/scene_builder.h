// Builds a World from a validated scene: materials, wall and fluid particles on lattices, and one
// solver instance per solver name (shared by the materials that name it).
#pragma once

#include <array>

#include <memory>

#include "framework/scene/scene.h"
#include "framework/solver/registry.h"
#include "framework/world/world.h"

namespace upf {

std::unique_ptr<World> build_world(const SceneDescription& scene, const Registry& registry,
                                   int threads);

// Boundary particles for a box container's walls: `layers` lattice layers just outside the inner
// box, the first at half a spacing from each face (fluid particles start half a spacing inside).
// Along the `open` axes (a periodic domain's) there are no walls.
void add_container_walls(Particles& particles, const Box& box, Real spacing, int layers,
                         MaterialId material, const std::array<bool, 3>& open = {});
// The liquid lattice of a fluid block: the whole box, or with `ball` the points inside the
// ellipsoid inscribed in it.
void add_fluid_block(Particles& particles, const Box& box, Real spacing, const Vec3& velocity,
                     Real particle_mass, MaterialId material, bool ball = false);

}  // namespace upf
