// One term of an exact fixed-point sum (CpuExecutor::fixed_point_sum and the device pipeline's),
// converted the same way on every backend. A value too large for the sum's range, infinite or
// NaN saturates at the term limit instead of being converted (which C++ leaves undefined): the
// sum then reads as huge, so a solver's stopping test fails and the world's stability check names
// the cause. NaN saturates upwards (an error sum that is NaN must not look converged). C++17.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "framework/core/real.h"

namespace upf {

// The largest |term| of a sum of `count` terms: 2^61 / count keeps a rank's sum within 2^61, so
// the ranks' sum of such totals fits in 64 bits for up to four saturated ranks. The sums solvers
// take stay many orders below it (a density error of 1e3 over 10^6 particles at 32 bits: 2^52).
UPF_HD inline double fixed_point_term_limit(std::size_t count) {
  return 2305843009213693952.0 / double(count > 0 ? count : 1);  // 2^61 / count
}

UPF_HD inline std::int64_t fixed_point_term(double value, double scale, double limit) {
  const double scaled = value * scale;
  if (!(scaled < limit)) return static_cast<std::int64_t>(limit);  // also NaN
  if (!(scaled > -limit)) return -static_cast<std::int64_t>(limit);
  return static_cast<std::int64_t>(nearbyint(scaled));
}

}  // namespace upf
