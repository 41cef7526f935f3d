// Spatial domains by recursive coordinate bisection (Berger & Bokhari 1987), computed by Zoltan
// (Boman et al., Sandia): boxes with equal summed particle weights (the work they cost), one per
// rank. Zoltan keeps the cuts, so any point has an owner and any box a list of ranks whose
// domains it touches (for ghosts).
// Which rank owns what never changes a result (particle_domain.h), so Zoltan's own choices need
// not be deterministic.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <vector>

#include "framework/core/vec3.h"

struct Zoltan_Struct;

namespace upf {

class ZoltanRcb {
 public:
  // The points of the current balance() call, which Zoltan's callbacks read.
  struct Points {
    const Vec3* x = nullptr;
    const float* weight = nullptr;
    std::size_t count = 0;
  };

  explicit ZoltanRcb(MPI_Comm comm);
  ~ZoltanRcb();
  ZoltanRcb(const ZoltanRcb&) = delete;
  ZoltanRcb& operator=(const ZoltanRcb&) = delete;

  // New cuts balancing the summed weights of the points every rank passes (its owned particles).
  void balance(const Vec3* points, const float* weights, std::size_t count);
  // The rank whose domain holds x.
  int owner(const Vec3& x) const;
  // Rank r's domain box; unbounded sides are +-DBL_MAX.
  void box(int r, double lo[3], double hi[3]) const;
  // The ranks whose domains touch the box [lo, hi], into `ranks`.
  void ranks_touching(const Vec3& lo, const Vec3& hi, std::vector<int>& ranks) const;

 private:
  Zoltan_Struct* zz_ = nullptr;
  int ranks_ = 1;
  Points points_;
  mutable std::vector<int> scratch_procs_, scratch_parts_;
};

}  // namespace upf
