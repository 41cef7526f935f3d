// An exact sum of per-particle values of any magnitude: the fixed-point sum of CpuExecutor (and
// of the device pipeline) with its binary point placed from the largest |value| over all ranks,
// so that the total cannot overflow and keeps about 60 bits below it. An iterative solver's dot
// products (a conjugate gradient's) steer its control flow, so they must be the same bits for any
// thread count, backend and rank count, but their scale changes by orders of magnitude as the
// solve converges: a fixed number of fraction bits would either overflow or round them to zero.
// C++17: nvcc builds it.
#pragma once

#include <cmath>
#include <cstddef>

#include "framework/executors/particle_range.h"

namespace upf {

// |value(i)|, for the scale.
template <class Value>
struct AbsoluteValue {
  Value value;
  UPF_HD double operator()(std::uint32_t i) const {
    const double v = double(value(i));
    return v < 0 ? -v : v;
  }
};

template <class Executor, class Value>
double scaled_fixed_point_sum(const Executor& exec, ParticleRange range, const Value& value) {
  const double largest = double(exec.max_of(range, AbsoluteValue<Value>{value}));
  if (!std::isfinite(largest)) return largest;
  if (largest == 0) return exec.fixed_point_sum(range, value);  // zero, or NaN terms: saturated
  const double bound = largest * double(exec.total(range.size) + 1);
  int exponent = 0;
  (void)std::frexp(bound, &exponent);  // bound < 2^exponent
  return exec.fixed_point_sum(range, value, 60 - exponent);
}

}  // namespace upf
