// A domain that repeats along one or more axes (a channel or a box without ends), as
// DualSPHysics and SPHinXsys offer for channel flows: what leaves through one face enters
// through the opposite one, and a particle near a face sees the particles near the opposite
// face as neighbours (their periodic images, shifted by the period).
//
// The box only does the geometry: wrapping positions into [lo, hi) and naming the shifts of a
// particle's images within reach. The domains (periodic_domain.h on one process,
// framework/mpi/ across ranks) hold the images as ghosts and refresh them after every stage.
#pragma once

#include "framework/core/vec3.h"

namespace upf {

struct PeriodicBox {
  // The most images a particle lends: a corner of a box periodic in three axes.
  static constexpr int kMaxImages = 7;

  bool periodic[3] = {false, false, false};
  Vec3 lo, hi;  // m; only the periodic axes' values matter

  UPF_HD bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  UPF_HD Real period(int axis) const { return hi[axis] - lo[axis]; }

  // Moves x into [lo, hi) along every periodic axis. A particle moves far less than a period
  // per step, so one shift suffices; the loop guards against a step that outran it.
  UPF_HD void wrap(Vec3& x) const {
    for (int a = 0; a < 3; ++a) {
      if (!periodic[a]) continue;
      const Real length = period(a);
      while (x[a] >= hi[a]) x[a] -= length;
      while (x[a] < lo[a]) x[a] += length;
    }
  }

  // The non-zero shifts s (combinations of +-period along periodic axes) for which x + s lies
  // within `reach` of the box: the images a particle at x must lend to particles inside. Into
  // shifts[0, kMaxImages), in a fixed order; returns how many.
  UPF_HD int image_shifts(const Vec3& x, Real reach, Vec3* shifts) const {
    // Per axis: the shifts that bring x within reach (0 always; +-period near a face).
    Real options[3][2];
    int counts[3];
    for (int a = 0; a < 3; ++a) {
      options[a][0] = 0;
      counts[a] = 1;
      if (!periodic[a]) continue;
      if (x[a] < lo[a] + reach)
        options[a][counts[a]++] = period(a);  // image past hi
      else if (x[a] >= hi[a] - reach)
        options[a][counts[a]++] = -period(a);  // image below lo
    }
    int found = 0;
    for (int k = 0; k < counts[2]; ++k)
      for (int j = 0; j < counts[1]; ++j)
        for (int i = 0; i < counts[0]; ++i) {
          if (i == 0 && j == 0 && k == 0) continue;
          shifts[found++] = Vec3{options[0][i], options[1][j], options[2][k]};
        }
    return found;
  }

  // visit(shift) for each of image_shifts, in its order.
  template <class Visit>
  void for_each_image_shift(const Vec3& x, Real reach, Visit&& visit) const {
    Vec3 shifts[kMaxImages];
    const int count = image_shifts(x, reach, shifts);
    for (int k = 0; k < count; ++k) visit(shifts[k]);
  }

  // x + shift, adding only along the shifted axes (the others keep their bits, -0 included).
  UPF_HD static Vec3 shifted(Vec3 x, const Vec3& shift) {
    for (int a = 0; a < 3; ++a)
      if (shift[a] != 0) x[a] += shift[a];
    return x;
  }
};

// How far past a face images reach for a support radius h: a little beyond h, so a neighbour at
// exactly h is not lost to the rounding of its shifted position.
UPF_HD inline Real periodic_image_reach(Real support_radius) {
  return support_radius * Real(1.0001);
}

}  // namespace upf
