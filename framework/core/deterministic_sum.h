// Reductions whose result does not depend on the thread count or on the particle order.
//
// Sums that steer control flow (the PCISPH stopping test) use fixed-point integers, which add
// associatively: any order, any thread count, the same bits. Sums that only feed metrics use
// fixed-size blocks added in index order, which is independent of the thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/executors/cpu/cpu_executor.h"
#include "framework/particles/kinetic_energy.h"

namespace upf {

// Sum of value(i) for i in [0, n), exact in fixed point (CpuExecutor::fixed_point_sum).
template <class Value>
double fixed_point_sum(const CpuExecutor& exec, std::size_t n, const Value& value,
                       int fraction_bits = 32) {
  return exec.fixed_point_sum(all_particles(n), value, fraction_bits);
}

// A running sum of doubles in 64-bit fixed point with 32 bits after the binary point (resolution
// 2.3e-10, magnitude below 2^31): exact, so the result is the same for any order of additions.
// For sums that feed bodies (per-body forces and torques). A value that is not finite, or a sum
// that leaves the range, makes the result NaN, which the world's stability check then reports.
class FixedPointAccumulator {
 public:
  void add(double value) {
    const double scaled = value * kScale;
    if (!(std::abs(scaled) < kLimit)) {
      broken_ = true;
      return;
    }
    if (__builtin_add_overflow(total_, static_cast<std::int64_t>(std::nearbyint(scaled)), &total_))
      broken_ = true;
  }
  double value() const { return broken_ ? std::nan("") : double(total_) / kScale; }

 private:
  static constexpr double kScale = 4294967296.0;  // 2^32
  static constexpr double kLimit = 9.2e18;        // below 2^63
  std::int64_t total_ = 0;
  bool broken_ = false;
};

// Sum of value(i) in blocks of 4096 added in index order: bitwise the same for any thread count.
template <class Value>
double block_sum(const CpuExecutor& exec, std::size_t n, Value&& value) {
  constexpr std::size_t kBlock = kBlockSumSize;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(blocks, 0.0);
  exec.for_each_index(blocks, [&](std::size_t b) {
    double s = 0;
    const std::size_t end = std::min(n, (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) s += double(value(i));
    partial[b] = s;
  });
  double total = 0;
  for (double p : partial) total += p;
  return total;
}

}  // namespace upf
