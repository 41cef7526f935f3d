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

// Writes boundary_volume for every particle of a type in `boundary` from `boundary_neighbours`
// (a list of boundary -> boundary neighbours, self excluded).
void compute_boundary_volumes(Particles& particles, TypeMask boundary,
                              const NeighbourList& boundary_neighbours,
                              const CubicSplineKernel& kernel, const CpuExecutor& exec);

}  // namespace upf
