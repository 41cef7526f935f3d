#include "solvers/fluid/compression_stats.h"

#include <algorithm>
#include <cstdint>

#include "framework/core/deterministic_sum.h"

namespace upf {

namespace {
Real relative_compression(const FluidView& f, const Real* density, std::uint32_t i) {
  const Real rho0 = f.rest_density[f.material[i]];
  return (density[i] - rho0) / rho0;
}
}  // namespace

double average_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                           const Real* density) {
  if (owned.empty()) return 0.0;
  const double sum = fixed_point_sum(exec, owned.size(), [&](std::size_t k) {
    return std::max(0.0, double(relative_compression(f, density, owned[k])));
  });
  return sum / double(owned.size());
}

double max_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                       const Real* density) {
  Real max_error = 0;
  const std::int64_t count = std::int64_t(owned.size());
#pragma omp parallel for schedule(static) reduction(max : max_error) num_threads(exec.threads())
  for (std::int64_t k = 0; k < count; ++k)
    max_error = std::max(max_error, relative_compression(f, density, owned[std::size_t(k)]));
  return double(max_error);
}

}  // namespace upf
