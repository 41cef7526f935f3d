#include "solvers/fluid/compression_stats.h"

#include "solvers/fluid/fluid_stages.h"

namespace upf {

double average_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                           const Real* density) {
  if (owned.empty()) return 0.0;
  const double sum =
      exec.fixed_point_sum(owned.range(), CompressionValue{f.rest_density, f.material, density});
  return sum / double(owned.size());
}

double max_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                       const Real* density) {
  return double(
      exec.max_of(owned.range(), CompressionValue{f.rest_density, f.material, density}));
}

}  // namespace upf
