// The wall normals of free-slip boundaries (a frozen or rigid material's "free_slip": 1), for the
// free-slip wall (Adami, Hu & Adams 2012, "A generalized wall boundary condition for smoothed
// particle hydrodynamics", J. Comput. Phys. 231, section 2.3, there with ghost velocities): in
// the viscous sums the wall takes the liquid's mean velocity along its surface and the no-slip one
// across it, so the wall viscosity never resists the liquid sliding along it as a whole
// (solvers/fluid/wall_velocity.h).
//
// A particle's normal is the axis of its boundary's shape around it,
//   g_b = sum_k (x_b - x_k) W_bk   over the boundary neighbours k of b's own body (or, for
//                                  particles of no body, of no body), n_b = g_b / |g_b|,
// which points off the wall's material on a wall of two or more layers. Only its axis matters
// (the free-slip velocity is even in n). Where the shape gives no axis (|g_b| under a twentieth
// of sum_k |x_b - x_k| W_bk: deep inside, or in the plane of a one-layer sheet) the normal is
// zero and the particle is a no-slip wall. Every particle takes this normal, a body's outer samples
// too: with their mesh normals instead, the samples of a plate's side faces damped the sheet that
// left over its edges, and a jet pushed the plate 3-4 % harder than with the shape's normals.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/boundary/slip_normal_fields.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/kernels/cubic_spline.h"
#include "framework/materials/material.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf {

// Per material: 1 for a boundary material with free_slip on. Throws InputError (naming
// /materials/NAME/free_slip) when a liquid with a boundary_viscosity solves its viscosity
// implicitly: the solve would hold the walls' slip velocity at the step's start, and a stiff
// liquid could then not slide along them faster than it did.
std::vector<std::uint8_t> free_slip_materials(const MaterialTable& materials);

// Declares kSlipNormalField (and, with body particles, kBodySlipNormalField) and writes them for
// the particles whose material m has free_slip[m] != 0, from `boundary_neighbours` (boundary ->
// boundary, self excluded). Body particles use their body-frame positions
// (kBodyLocalPositionField) where that field exists, and get body-frame normals.
void compute_slip_normals(Particles& particles, const std::vector<std::uint8_t>& free_slip,
                          const NeighbourList& boundary_neighbours, const CubicSplineKernel& kernel,
                          const CpuExecutor& exec);

}  // namespace upf
