#include "framework/particles/particle_identity.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/core/fnv1a.h"

namespace upf {

namespace {

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string at(std::size_t i, const Particles& p) {
  return " (particle " + std::to_string(i) + ", id " + std::to_string(p.id[i]) + ")";
}

}  // namespace

std::optional<std::string> particle_array_problem(const Particles& p,
                                                  const std::vector<ParticleType>& material_types) {
  const ParticleId bound = p.id_bound();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.id[i] >= bound)
      return "particle id " + std::to_string(p.id[i]) + " is at or beyond the id counter " +
             std::to_string(bound);
    if (int(p.type[i]) >= kParticleTypeCount)
      return "particle type " + std::to_string(int(p.type[i])) + " is unknown" + at(i, p);
    if (std::size_t(p.material[i]) >= material_types.size())
      return "material " + std::to_string(p.material[i]) + " does not exist" + at(i, p);
    if (material_types[p.material[i]] != p.type[i])
      return "a particle of type " + std::to_string(int(p.type[i])) + " has material " +
             std::to_string(p.material[i]) + ", of another type" + at(i, p);
    if (p.body[i] < kNoBody)
      return "body id " + std::to_string(p.body[i]) + " is negative" + at(i, p);
    if (!finite(p.position[i])) return "a position is not finite" + at(i, p);
    if (!finite(p.velocity[i])) return "a velocity is not finite" + at(i, p);
    if (!std::isfinite(p.mass[i])) return "a mass is not finite" + at(i, p);
    if (!std::isfinite(p.boundary_volume[i])) return "a boundary volume is not finite" + at(i, p);
  }
  // Sorted rather than marked in a table by id: the id counter grows with every emitted
  // particle, so a table could be far larger than the particles.
  std::vector<ParticleId> ids(p.id.begin(), p.id.begin() + std::ptrdiff_t(p.size()));
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  if (twice != ids.end()) return "particle id " + std::to_string(*twice) + " appears twice";
  return std::nullopt;
}

std::uint64_t particle_identity(const Particles& p) {
  std::vector<std::uint32_t> kept;  // the particles that are not liquid, in id order
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] != ParticleType::Liquid) kept.push_back(std::uint32_t(i));
  std::sort(kept.begin(), kept.end(),
            [&](std::uint32_t a, std::uint32_t b) { return p.id[a] < p.id[b]; });
  Fnv1a hash;
  for (const std::uint32_t i : kept) {
    hash.add(p.id[i]);
    hash.add(std::uint8_t(p.type[i]));
    hash.add(p.material[i]);
    hash.add(p.body[i]);
  }
  hash.add(std::uint64_t(kept.size()));
  return hash.value();
}

}  // namespace upf
