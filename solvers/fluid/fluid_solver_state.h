// The state every fluid solver keeps and the stages they all run the same way, so that comparing
// fluid solvers isolates the pressure solver (DESIGN.md, "Solvers"):
//   begin_step       the owned index list and the view of the current state;
//   shared_forces    "non_pressure": density and kernel gradients at the current positions, then
//                    a_other = g + viscosity (fluid_forces.h);
//   integrate        symplectic Euler, v += (a_other + a_pressure) dt, then x += v dt.
// The pressure stage between shared_forces and integrate is each solver's own.
#pragma once

#include <vector>

#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

struct FluidSolverState {
  FluidMaterialTable table;
  FluidNeighbourHandles lists;
  OwnedParticles owned;
  Real max_viscosity = 0;  // [m^2/s] largest kinematic viscosity of the owned materials

  // Per-step buffers, rewritten every step (so they need no reordering with the particles).
  std::vector<Vec3> fluid_gradient;         // grad W_ij per fluid-list slot
  std::vector<Vec3> boundary_gradient;      // per particle: sum_b V_b grad W_ib
  std::vector<Vec3> other_acceleration;     // per particle: gravity + shared viscosity
  std::vector<Vec3> pressure_acceleration;  // per particle: the solver's pressure term

  // Creates the exported fields `density` and `pressure`, requests the neighbour lists and loads
  // the constants of `materials`.
  void prepare(World& world, const std::vector<MaterialId>& materials);
  // Rebuilds the owned list, sizes the buffers for this step's lists; the current state's view.
  FluidView begin_step(const World& world);
  // Writes density (field `density`), the kernel gradients and other_acceleration.
  void shared_forces(const World& world, const FluidView& f, Real* density);
  // Symplectic Euler over the owned particles with other_acceleration + pressure_acceleration.
  void integrate(World& world, Real dt) const;
};

}  // namespace upf
