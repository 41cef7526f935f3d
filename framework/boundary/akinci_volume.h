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

// Name of an optional per-particle field holding the known volume of a boundary particle
// (0 where unknown). Container walls are regular lattices of two or more layers: their volume is
// the lattice cell, the value 1/sum W_bk takes inside a complete lattice. Akinci's sum over the
// sampled wall alone misses the neighbours on the fluid side: 18 % too large on flat walls (two
// layers, cubic spline, H = 2 spacings), too small along edges and corners, where fluid then
// packed closer and stayed 3.9 % compressed in the hydrostatic tank.
inline constexpr const char* kKnownBoundaryVolumeField = "boundary.known_volume";

// Writes boundary_volume for every particle of a type in `boundary` from `boundary_neighbours`
// (a list of boundary -> boundary neighbours, self excluded) that belong to the same body (or,
// for particles of no body, to no body), or the particle's kKnownBoundaryVolumeField value
// where that field exists and is positive.
void compute_boundary_volumes(Particles& particles, TypeMask boundary,
                              const NeighbourList& boundary_neighbours,
                              const CubicSplineKernel& kernel, const CpuExecutor& exec);

}  // namespace upf
