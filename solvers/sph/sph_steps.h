// SPH's own stages in the order its step runs them (Müller et al. 2003), for any executor:
// SphSolver runs them on the CPU executor, the device pipeline on its backends (device/).
// C++17: nvcc builds it too.
#pragma once

#include <type_traits>

#include "framework/executors/particle_range.h"
#include "solvers/fluid/boundary_reactions.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/sph/sph_kernel_sets.h"
#include "solvers/sph/sph_kernels.h"

namespace upf {

// SPH's choice of kernels: the cubic spline for everything, or the paper's set with poly6
// densities scaled to the rest density on the initial lattice (SphSolver::poly6_lattice_scale).
struct SphKernelChoice {
  bool cubic_spline;
  Real support_radius;
  Real poly6_scale;

  // visit(kernels, density_scale) with the set in use (host code: it picks the stages to run).
  template <class Visit>
  void with_kernels(Visit&& visit) const {
    if (cubic_spline) {
      visit(CubicKernelSet{CubicSplineKernel(support_radius)}, Real(1));
    } else {
      visit(MullerKernelSet{MullerKernels(support_radius)}, poly6_scale);
    }
  }
};

// After the shared non-pressure forces: the set's own density (not for the cubic spline, whose
// density is already there) once the shared viscosity has read the spline density, then the
// paper's viscosity when mu > 0.
template <class Executor>
void run_sph_non_pressure(const Executor& exec, ParticleRange owned, const FluidView& f,
                          const SphKernelChoice& choice, Real mu, Real* density, Vec3* a_other) {
  choice.with_kernels([&](const auto& kernels, Real density_scale) {
    using Kernels = std::decay_t<decltype(kernels)>;
    if (!choice.cubic_spline)
      exec.run(owned, SphDensityStage<Kernels>{f, kernels, density_scale, density});
    if (mu > 0) exec.run(owned, SphViscosityStage<Kernels>{f, kernels, density, mu, a_other});
  });
}

// p = k (rho - rho0), then the paper's symmetrised pressure force.
template <class Executor>
void run_sph_pressure(const Executor& exec, ParticleRange owned, const FluidView& f,
                      const SphKernelChoice& choice, Real stiffness, const Real* density,
                      Real* pressure, Vec3* a_pressure) {
  exec.run(owned, SphPressureStage{f, density, stiffness, pressure});
  choice.with_kernels([&](const auto& kernels, Real) {
    using Kernels = std::decay_t<decltype(kernels)>;
    exec.run(owned,
             SphPressureAccelerationStage<Kernels>{f, kernels, density, pressure, a_pressure});
  });
}

// The reactions on rigid particles (boundary_reactions.h) of sph_pressure_acceleration's boundary
// term: P_i = p_i / (2 rho_i^2), with the pressure kernel of the set in use.
template <class Executor>
void run_sph_reactions(const Executor& exec, std::size_t n, const FluidView& f,
                       NeighbourView fluid_of_boundary, const SphKernelChoice& choice,
                       const Real* density, const Real* pressure, OwnedMaterials owns,
                       Vec3* force) {
  choice.with_kernels([&](const auto& kernels, Real) {
    using Kernels = std::decay_t<decltype(kernels)>;
    run_boundary_reactions(exec, n, f, fluid_of_boundary, density, owns,
                           PressureOverDensitySquared{pressure, density, Real(0.5)},
                           KernelSetPressureGradient<Kernels>{kernels}, force);
  });
}

}  // namespace upf
