// WCSPH's own stages in the order its step runs them (Becker & Teschner 2007), for any executor:
// WcsphSolver runs them on the CPU executor, the device pipeline on its backends (device/).
// C++17: nvcc builds it too.
#pragma once

#include "framework/executors/particle_range.h"
#include "solvers/wcsph/wcsph_kernels.h"

namespace upf {

// After the shared non-pressure forces: the artificial viscosity (eq. 11), when 2 alpha h c > 0.
template <class Executor>
void run_wcsph_viscosity(const Executor& exec, ParticleRange owned, const FluidView& f,
                         const Real* density, FluidGradients fluid_gradient, Real two_alpha_h_c,
                         Vec3* a_other) {
  if (!(two_alpha_h_c > 0)) return;
  exec.run(owned, ArtificialViscosityStage{f, density, fluid_gradient, two_alpha_h_c, a_other});
}

// Pressures from the Tait equation (eq. 6), then the pressure accelerations (eq. 5).
template <class Executor>
void run_wcsph_pressure(const Executor& exec, ParticleRange owned, const FluidView& f,
                        const Real* density, const Real* tait_factor, Real* pressure,
                        FluidGradients fluid_gradient, const Vec3* boundary_gradient,
                        Vec3* a_pressure) {
  exec.run(owned, TaitPressureStage{f, density, tait_factor, pressure});
  exec.run(owned, WcsphPressureAccelerationStage{f, density, pressure, fluid_gradient,
                                                 boundary_gradient, a_pressure});
}

}  // namespace upf
