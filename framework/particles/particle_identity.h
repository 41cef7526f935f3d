// Checks that particle arrays read from a checkpoint are a sound state of this world before the
// world takes them: a checkpoint with a valid checksum may still hold anything (a flipped bit
// re-sealed, a file of another scene), and ids index arrays, types and materials pick stages,
// positions pick grid cells. Nothing here trusts the stream: every check is bounded by the
// world's own id counter and material count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "framework/particles/particles.h"

namespace upf {

// The first problem in `p` that would crash or corrupt a run, or nothing: an id at or beyond the
// id counter or repeated, a material out of range (`material_types`: each material's particle
// type) or of another type than the particle, a body id below kNoBody, a position, velocity,
// mass or boundary volume that is not finite.
std::optional<std::string> particle_array_problem(const Particles& p,
                                                  const std::vector<ParticleType>& material_types);

// What makes the particles this scene's: FNV-1a 64 over, in id order, the id, type, material and
// body of every particle that is not liquid (walls, bodies, grains), and their count. Liquid
// comes and goes (emitters, sinks: DESIGN.md, "Particles that come and go"); everything else is
// the same in a world and in any checkpoint of it. `p` must pass particle_array_problem.
std::uint64_t particle_identity(const Particles& p);

}  // namespace upf
