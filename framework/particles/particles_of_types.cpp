#include "framework/particles/particles_of_types.h"

#include <cstdint>
#include <vector>

namespace upf {

Particles particles_of_types(const Particles& all, TypeMask types) {
  Particles out;
  all.snapshot_into(out);
  std::vector<std::uint8_t> doomed(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) doomed[i] = in_mask(types, out.type[i]) ? 0 : 1;
  out.remove(doomed);
  return out;
}

bool all_of_types(const Particles& all, TypeMask types) {
  for (const ParticleType t : all.type)
    if (!in_mask(types, t)) return false;
  return true;
}

}  // namespace upf
