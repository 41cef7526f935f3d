// The density-error statistics every fluid solver reports, defined once so that `upf compare`
// compares like with like: the relative compression e_i = (rho_i - rho0_i) / rho0_i of the
// owned particles, with
//   average = (1/N) sum_i max(0, e_i)   summed in fixed point: the same bits for any thread count
//   maximum = max(0, max_i e_i)         exact
// Expansion (e_i < 0, at the free surface) counts as no error.
#pragma once

#include "framework/executors/cpu/cpu_executor.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

double average_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                           const Real* density);
double max_compression(const CpuExecutor& exec, const OwnedParticles& owned, const FluidView& f,
                       const Real* density);

}  // namespace upf
