#include "solvers/fluid/compression_stats.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/executors/average_over.h"
#include "solvers/fluid/fluid_stages.h"

namespace upf {

double average_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                           const Real* density) {
  return average_over(exec, owned.range(), CompressionValue{f.rest_density, f.material, density});
}

double max_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                       const Real* density) {
  return double(exec.max_of(owned.range(), CompressionValue{f.rest_density, f.material, density}));
}

namespace {
// The compression of the k-th listed particle into out[k].
struct ListedCompressionStage {
  ParticleRange listed;
  CompressionValue value;
  Real* out;
  UPF_HD void operator()(std::uint32_t k) const { out[k] = value(listed[k]); }
};
}  // namespace

double StoppingError::operator()(const CpuExecutor& exec, const OwnedParticles& owned,
                                 const FluidView& f, const Real* density) {
  if (percentile_ <= 0) return average_compression(exec, owned, f, density);
  if (percentile_ >= 100) return max_compression(exec, owned, f, density);
  if (owned.empty()) return 0.0;
  compressions_.resize(owned.size());
  exec.run(
      all_particles(owned.size()),
      ListedCompressionStage{owned.range(), CompressionValue{f.rest_density, f.material, density},
                             compressions_.data()});
  // The value below which `percentile_` % of the particles lie (nearest rank).
  const auto rank =
      std::size_t(std::max(1.0, std::ceil(percentile_ / 100.0 * double(owned.size())))) - 1;
  std::nth_element(compressions_.begin(), compressions_.begin() + std::ptrdiff_t(rank),
                   compressions_.end());
  return double(compressions_[rank]);
}

std::string StoppingError::cannot_split() const {
  // A selection over every rank's particles would gather them all: not offered across ranks.
  if (percentile_ <= 0 || percentile_ >= 100) return {};
  return "stop_percentile " + std::to_string(percentile_) +
         " needs every particle's compression in one place; across MPI ranks use 0 (the "
         "average) or 100 (the largest)";
}

ParamSpec wall_pressure_spec() {
  return {"wall_pressure",
          "1",
          0,
          0,
          1,
          "1: frozen walls carry the fluid's pressure, extrapolated hydrostatically (Adami et al. "
          "2012), so the layer on a wall reads rho0 g d; 0: Akinci et al. 2012's term alone, under "
          "which it reads about 1.7 times that. Off by default: with it IISPH and DFSPH need eta "
          "0.2 % to keep a tank's wall layer quiet, WCSPH tanks ring for longer, and PCISPH's "
          "largest compression on DamBreakModel rises from 2.9 to 4.6 % "
          "(docs/boundary-pressure.md)"};
}

ParamSpec stop_percentile_spec() {
  return {"stop_percentile",
          "%",
          0,
          0,
          100,
          "which compression the stopping test bounds by eta: 0 the average (as the papers), "
          "100 the largest particle's, in between that percentile of the particles' "
          "compressions (docs/solvers.md, Density-error statistics)"};
}

}  // namespace upf
