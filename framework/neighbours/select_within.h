// Picking the candidates within the search radius out of a scanned cell block, without a branch
// per candidate: about one candidate in five is a neighbour, which defeats branch prediction, and
// the scalar form (store the index, advance by the comparison) made each candidate wait on the
// previous one's count; it was 38 % of the neighbour scan's samples on DamBreakModel (perf).
// With SSE2 (every x86-64) four squared distances are compared at once and their indices stored
// from a table by the 4-bit mask, the output advancing by the mask's population count.
#pragma once

#include <cstddef>
#include <cstdint>

#include "framework/core/real.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace upf {

// Writes the indices k < m with d2[k] < r2 to `hit` in increasing order and returns their count.
// `hit` must have room for m + 3 entries (a group of four stores four).
inline std::size_t select_within(const Real* d2, std::size_t m, Real r2, std::uint32_t* hit) {
  std::size_t hits = 0, k = 0;
#if defined(__SSE2__)
  if constexpr (sizeof(Real) == sizeof(float)) {
    // For each 4-bit mask, the positions of its set bits, packed to the front.
    alignas(16) static constexpr std::uint32_t kPacked[16][4] = {
        {0, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {2, 0, 0, 0}, {0, 2, 0, 0},
        {1, 2, 0, 0}, {0, 1, 2, 0}, {3, 0, 0, 0}, {0, 3, 0, 0}, {1, 3, 0, 0}, {0, 1, 3, 0},
        {2, 3, 0, 0}, {0, 2, 3, 0}, {1, 2, 3, 0}, {0, 1, 2, 3}};
    static constexpr std::uint8_t kCount[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
    const __m128 radius2 = _mm_set1_ps(float(r2));
    for (; k + 4 <= m; k += 4) {
      const __m128 inside =
          _mm_cmplt_ps(_mm_loadu_ps(reinterpret_cast<const float*>(d2) + k), radius2);
      const int mask = _mm_movemask_ps(inside);
      const __m128i packed = _mm_load_si128(reinterpret_cast<const __m128i*>(kPacked[mask]));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(hit + hits),
                       _mm_add_epi32(packed, _mm_set1_epi32(int(k))));
      hits += kCount[mask];
    }
  }
#endif
  for (; k < m; ++k) {
    hit[hits] = std::uint32_t(k);
    hits += d2[k] < r2;
  }
  return hits;
}

}  // namespace upf
