// Makes room for a body in the fluid it was placed in: liquid particles whose centres lie inside
// the body's mesh, or within half a spacing of its surface, are removed before the run starts.
// Otherwise a body placed in water would start full of fluid, which its boundary pushes out
// explosively (SPlisHSPlasH and DualSPHysics likewise fill fluid blocks around obstacles).
// Open meshes (allowed for static obstacles) have no inside: only the surface's skin is carved.
#pragma once

#include <cstddef>

#include "coupling/bodies/body_source.h"
#include "framework/particles/particles.h"

namespace upf {

// Returns how many liquid particles were removed.
std::size_t carve_fluid(Particles& particles, const BodySource& body, double spacing);

}  // namespace upf
