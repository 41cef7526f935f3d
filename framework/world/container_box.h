// A container's inner box: the walls' particle layers lie outside it. Solvers that treat walls
// as exact planes (DEM) read the six inner faces from here; fluids see the wall particles.
#pragma once

#include "framework/core/vec3.h"
#include "framework/particles/particles.h"

namespace upf {

struct ContainerBox {
  Vec3 min, max;  // m
  MaterialId material = 0;
};

}  // namespace upf
