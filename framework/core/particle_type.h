// The four particle types of the unified world. The type routes a particle to the family of
// solvers that may move it (FleX calls these phases); the material picks the solver itself.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace upf {

enum class ParticleType : std::uint8_t { Liquid = 0, Rigid = 1, Granular = 2, Frozen = 3 };

inline constexpr int kParticleTypeCount = 4;

// A set of particle types as bit flags, used to select neighbour pairs and probe targets.
using TypeMask = std::uint8_t;

constexpr TypeMask mask_of(ParticleType t) {
  return TypeMask(1u << static_cast<unsigned>(t));
}
constexpr TypeMask kLiquidMask = mask_of(ParticleType::Liquid);
constexpr TypeMask kBoundaryMask = mask_of(ParticleType::Rigid) | mask_of(ParticleType::Frozen);
constexpr TypeMask kAllTypes = 0x0F;

constexpr bool in_mask(TypeMask m, ParticleType t) {
  return (m & mask_of(t)) != 0;
}

// A flag of a neighbour query beside the type bits: of the query's types, only the particles of a
// body (a body id set). The reactions on a static body need the liquid around its particles, not
// around every wall particle, whose type (frozen) it shares.
constexpr TypeMask kOfBodiesOnly = 0x10;

// Whether a neighbour query `query` lists the neighbours of a particle of type t (of_a_body: the
// particle belongs to a body).
constexpr bool query_takes(TypeMask query, ParticleType t, bool of_a_body) {
  return in_mask(query, t) && (of_a_body || (query & kOfBodiesOnly) == 0);
}

constexpr std::string_view to_string(ParticleType t) {
  switch (t) {
    case ParticleType::Liquid:
      return "liquid";
    case ParticleType::Rigid:
      return "rigid";
    case ParticleType::Granular:
      return "granular";
    case ParticleType::Frozen:
      return "frozen";
  }
  return "unknown";
}

inline std::optional<ParticleType> parse_particle_type(std::string_view s) {
  for (int i = 0; i < kParticleTypeCount; ++i) {
    auto t = static_cast<ParticleType>(i);
    if (s == to_string(t)) return t;
  }
  return std::nullopt;
}

}  // namespace upf
