// Morton (Z-order) keys of integer cell coordinates: 21 bits per axis interleaved into 63 bits,
// so cells that are close in space are close in the sorted particle order.
#pragma once

#include <cstdint>

#include "framework/core/real.h"

namespace upf {

inline constexpr std::uint32_t kMortonAxisBits = 21;
inline constexpr std::uint32_t kMortonAxisMax = (1u << kMortonAxisBits) - 1;

UPF_HD constexpr std::uint64_t spread_bits_3d(std::uint32_t v) {
  std::uint64_t x = v & 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

UPF_HD constexpr std::uint64_t morton_key(std::uint32_t cx, std::uint32_t cy, std::uint32_t cz) {
  return spread_bits_3d(cx) | (spread_bits_3d(cy) << 1) | (spread_bits_3d(cz) << 2);
}

}  // namespace upf

namespace upf {

// Inverse of spread_bits_3d: gathers every third bit back into a 21-bit integer.
UPF_HD constexpr std::uint32_t compact_bits_3d(std::uint64_t v) {
  v &= 0x1249249249249249ULL;
  v = (v ^ (v >> 2)) & 0x10c30c30c30c30c3ULL;
  v = (v ^ (v >> 4)) & 0x100f00f00f00f00fULL;
  v = (v ^ (v >> 8)) & 0x1f0000ff0000ffULL;
  v = (v ^ (v >> 16)) & 0x1f00000000ffffULL;
  v = (v ^ (v >> 32)) & 0x1fffffULL;
  return std::uint32_t(v);
}

}  // namespace upf
