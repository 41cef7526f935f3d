// The template neighbourhood of a particle inside the initial cubic lattice: the offsets
// (i, j, k) * spacing with |i|, |j|, |k| <= ceil(support / spacing), the centre included.
// Solvers evaluate kernel sums over it once in prepare() (PCISPH's delta, SPH's poly6 density).
#pragma once

#include <cmath>

#include "framework/core/vec3.h"

namespace upf {

template <class Visit>
void for_each_lattice_offset(Real spacing, Real support_radius, Visit&& visit) {
  const int reach = int(std::ceil(support_radius / spacing));
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = -reach; k <= reach; ++k)
        visit(Vec3{Real(i) * spacing, Real(j) * spacing, Real(k) * spacing});
}

}  // namespace upf
