// The average of a particle value over a range, exact and the same on every executor: a
// fixed-point sum over the total count. On a world split over ranks both the sum and the count
// are global (CpuExecutor::total), so the average is the one-rank average to the bit, and every
// rank calls the same reductions even where it holds none of the particles. C++17: nvcc builds it.
#pragma once

#include <cstddef>

#include "framework/executors/particle_range.h"

namespace upf {

template <class Executor, class Value>
double average_over(const Executor& exec, ParticleRange range, const Value& value) {
  const std::size_t total = exec.total(range.size);
  const double sum = exec.fixed_point_sum(range, value);
  return total == 0 ? 0.0 : sum / double(total);
}

}  // namespace upf
