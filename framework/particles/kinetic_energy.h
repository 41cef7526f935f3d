// The kinetic energy the metrics report, sum_i m_i |v_i|^2 / 2, summed in index-order blocks
// (block_sum, deterministic_sum.h) so that it is the same bits for any thread count and for the
// device pipeline, which sums the same blocks (device/). C++17 and UPF_HD.
#pragma once

#include <cstddef>

#include "framework/core/vec3.h"

namespace upf {

// Particles per block of block_sum: each block is summed in index order, then the blocks in order.
inline constexpr std::size_t kBlockSumSize = 4096;

struct KineticEnergyValue {
  const Real* mass;
  const Vec3* velocity;
  UPF_HD double operator()(std::size_t i) const {
    return 0.5 * double(mass[i]) * double(squared_norm(velocity[i]));
  }
};

}  // namespace upf
