// The density-error statistics every fluid solver reports, defined once so that `upf compare`
// compares like with like: the relative compression e_i = (rho_i - rho0_i) / rho0_i of the
// owned particles, with
//   average = (1/N) sum_i max(0, e_i)   summed in fixed point: the same bits for any thread count
//   maximum = max(0, max_i e_i)         exact
// Expansion (e_i < 0, at the free surface) counts as no error.
#pragma once

#include <string>
#include <vector>

#include "framework/executors/cpu/cpu_executor.h"
#include "framework/params/param_spec.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

double average_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                           const Real* density);
double max_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                       const Real* density);

// The error an iterative solver's stopping test bounds, chosen by the scene (`stop_percentile`):
// 0, the average compression, as PCISPH, IISPH and DFSPH's papers bound it (one fixed-point sum
// per iteration); 100, the largest (one exact maximum); in between, that percentile of the
// owned particles' compressions (a copy and a selection over them per iteration). The average
// lets a few particles stay far compressed: on the demo scene PCISPH stopped at an average of
// 0.3 % with single particles at 3-15 %. Every choice is exact, so the iteration count is the
// same for any thread count.
class StoppingError {
 public:
  explicit StoppingError(double percentile = 0) : percentile_(percentile) {}
  bool is_average() const { return percentile_ <= 0; }
  // Why it cannot run on a world split over ranks (Solver::cannot_split), or empty.
  std::string cannot_split() const;
  double percentile() const { return percentile_; }
  double operator()(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                    const Real* density);

 private:
  double percentile_;
  std::vector<Real> compressions_;  // scratch for percentiles
};

// The scene parameter every iterative fluid solver offers for StoppingError.
ParamSpec stop_percentile_spec();
// The parameter "wall_pressure" of the fluid solvers (boundary_pressure.h), off by default.
ParamSpec wall_pressure_spec();

}  // namespace upf
