// The SPH density summation over a neighbour list, sum_k c_j W(|x_i - x_j|) with j = j_k the
// neighbour in list slot k (Monaghan 1992), written so that the compiler vectorises it: every
// fluid solver's density at current or predicted positions (fluid_forces.h).
//
// Why not a plain loop: one running sum makes every pair wait for the previous addition, and the
// cubic spline's two branches are taken at random; PCISPH's density at predicted positions, such
// a loop, was 27 % of DamBreakModel's time (perf, 2 threads). On the host the pairs go through
// in chunks: their offsets are gathered into coordinate arrays, the kernel is evaluated without
// branches in a loop the compiler vectorises, and the terms are added into four partial sums by
// list slot, (k - begin) mod 4, which are added pairwise at the end. That order is fixed by the
// source, not by the compiler or the thread count, so the host path and the device pipeline's
// OpenMP instantiation give the same bits. A pair's term has the plain loop's bits (the same
// operations in the same order); only the order of the additions differs. CUDA threads keep the
// plain loop.
//
// The same staging did not pay for the loops that need gradients (the density and gradients, the
// pressure acceleration, the viscosity): they have three independent sums and no square root or
// branch left to vectorise, and copying their inputs into arrays made them 25-90 % slower.
#pragma once

#include <cstdint>

#include "framework/core/vec3.h"
#include "framework/kernels/cubic_spline.h"

namespace upf {

// The coefficient c_j read from a per-particle array (masses, boundary volumes).
struct ArrayWeight {
  const Real* values;
  UPF_HD Real operator()(std::uint32_t j) const { return values[j]; }
};

// sum_k weight(j_k) W(|xi - x[j_k]|) over list slots k in [begin, end).
template <class Weight>
UPF_HD inline Real kernel_sum(const CubicSplineKernel& kernel, const Vec3& xi, const Vec3* x,
                              const std::uint32_t* indices, std::uint32_t begin, std::uint32_t end,
                              const Weight& weight) {
#if defined(__CUDA_ARCH__)
  Real sum = 0;
  for (std::uint32_t k = begin; k < end; ++k) {
    const std::uint32_t j = indices[k];
    sum += weight(j) * kernel.value(norm(xi - x[j]));
  }
  return sum;
#else
  // Every chunk has kChunk slots whatever the list's length, a short one padded with zero
  // weights at offsets outside the support: the loops then have fixed trip counts and vectorise
  // whole, and a padded term adds nothing.
  constexpr std::uint32_t kChunk = 16;  // a multiple of the four partial sums
  const Real outside = Real(2) * kernel.support_radius();
  Real partial[4] = {0, 0, 0, 0};
  for (std::uint32_t first = begin; first < end; first += kChunk) {
    const std::uint32_t count = end - first < kChunk ? end - first : kChunk;
    Real dx[kChunk], dy[kChunk], dz[kChunk], term[kChunk];
    for (std::uint32_t s = 0; s < count; ++s) {
      const std::uint32_t j = indices[first + s];
      const Vec3 d = xi - x[j];
      dx[s] = d.x;
      dy[s] = d.y;
      dz[s] = d.z;
      term[s] = weight(j);
    }
    for (std::uint32_t s = count; s < kChunk; ++s) {
      dx[s] = outside;
      dy[s] = dz[s] = term[s] = 0;
    }
    // squared_norm's order of additions, so that each W has value()'s bits
    for (std::uint32_t s = 0; s < kChunk; ++s)
      term[s] *=
          kernel.value_without_branches(std::sqrt(dx[s] * dx[s] + dy[s] * dy[s] + dz[s] * dz[s]));
    for (std::uint32_t s = 0; s < kChunk; s += 4)
      for (std::uint32_t lane = 0; lane < 4; ++lane) partial[lane] += term[s + lane];
  }
  return (partial[0] + partial[1]) + (partial[2] + partial[3]);
#endif
}

}  // namespace upf
