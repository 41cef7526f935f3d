// The particles of some types only, as a Particles of their own: what a frame format that
// writes fewer types than the world holds (liquid-only PLY, the frozen piece) writes.
#pragma once

#include "framework/core/particle_type.h"
#include "framework/particles/particles.h"

namespace upf {

// The particles of `all` whose type is in `types`, in their order, with the built-in arrays and
// the exported fields (as Particles::snapshot_into copies them).
Particles particles_of_types(const Particles& all, TypeMask types);

// True when every particle of `all` has a type in `types` (nothing to leave out).
bool all_of_types(const Particles& all, TypeMask types);

}  // namespace upf
