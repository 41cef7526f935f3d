// EquationOfStateSolver's step statistics on the device pipeline: one iteration, the average
// compression by an exact fixed-point sum and the largest exactly (compression_stats.h's values).
#pragma once

#include "framework/solver/solver.h"
#include "solvers/fluid/fluid_stages.h"

namespace upf::device {

template <class Executor, class Step>
SolverStats state_equation_stats(const Executor& exec, const Step& s) {
  SolverStats stats;
  stats.iterations = 1;
  const CompressionValue compression{s.f.rest_density, s.f.material, s.density};
  if (s.owned.size > 0)
    stats.avg_density_error = exec.fixed_point_sum(s.owned, compression) / double(s.owned.size);
  stats.max_density_error = double(exec.max_of(s.owned, compression));
  return stats;
}

}  // namespace upf::device
