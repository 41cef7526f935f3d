// Boundary particle volumes of Akinci et al. 2012, "Versatile rigid-fluid coupling for
// incompressible SPH" (ACM TOG 31(4)): V_b = 1 / sum_k W_bk over the boundary neighbours k of b
// (b included). Fluids then see a boundary particle as Psi_b = rho0 V_b, which corrects for
// irregular and one-layer samplings alike.
#pragma once

#include "framework/core/particle_type.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/kernels/cubic_spline.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf {

// Name of an optional per-particle field that scales the Akinci volume (see wall_volume_scale).
inline constexpr const char* kBoundaryVolumeScaleField = "boundary.volume_scale";

// Writes boundary_volume for every particle of a type in `boundary` from `boundary_neighbours`
// (a list of boundary -> boundary neighbours, self excluded), times the particle's
// kBoundaryVolumeScaleField value when that field exists.
void compute_boundary_volumes(Particles& particles, TypeMask boundary,
                              const NeighbourList& boundary_neighbours,
                              const CubicSplineKernel& kernel, const CpuExecutor& exec);

}  // namespace upf

namespace upf {

// The fluid-facing layer of a sampled wall has no boundary neighbours on its fluid side, so
// 1/sum W overestimates its volume (by 18 % for two lattice layers with the cubic spline at
// H = 2 spacings), and fluid resting against the wall would start 2.6 % compressed. This factor
// rescales the Akinci volumes of a flat lattice wall of `layers` layers so that a fluid particle
// one spacing from it sees exactly the missing half of its neighbourhood:
//   gamma = sum_{fluid side missing} W dx^3 / sum_{wall particles} V_b W.
Real wall_volume_scale(const CubicSplineKernel& kernel, Real spacing, int layers);

}  // namespace upf
