// The state every fluid solver keeps and the stages they all run the same way, so that comparing
// fluid solvers isolates the pressure solver (DESIGN.md, "Solvers"):
//   begin_step       the owned index list and the view of the current state;
//   shared_forces    "non_pressure": density and kernel gradients at the current positions, then
//                    a_other = g + viscosity (fluid_forces.h) + surface tension and adhesion
//                    (surface_forces.h, when a liquid has a sigma) + the force of other materials
//                    (CouplingArray::LiquidForce: grains' drag and buoyancy reactions) / m;
//   add_reactions    the reactions on body particles (boundary_reactions.h), at the
//                    positions and velocities the forces used, so before integrate;
//   integrate        symplectic Euler, v += (a_other + a_pressure) dt, then x += v dt.
// The pressure stage between shared_forces and integrate is each solver's own.
#pragma once

#include <vector>

#include "framework/world/world.h"
#include "solvers/fluid/boundary_reactions.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

// What every fluid solver declares in its registration (SolverInfo::coupling): it writes its
// reactions on bodies and applies the forces of other materials (grains) when those exist.
inline CouplingUse fluid_solver_coupling() {
  return {{CouplingArray::BoundaryForce}, {}, {CouplingArray::LiquidForce}};
}

struct FluidSolverState {
  FluidMaterialTable table;
  // The solver's choice of wall pressure (boundary_pressure.h; its parameter "wall_pressure"),
  // put into every FluidView.
  bool wall_pressure = false;
  FluidNeighbourHandles lists;
  // Body particles -> liquid, when a body system collects reactions: rigid particles, and the
  // frozen ones of static and kinematic bodies where there are any (reaction_query).
  int reaction_list = -1;
  TypeMask reaction_query = 0;
  // With wall friction (a boundary_viscosity > 0): boundary -> liquid, for the walls' velocities
  // in the viscous sums (wall_velocity.h), and their field.
  int wall_list = -1;
  FieldHandle<Vec3> wall_velocity_field;
  Vec3* wall_velocity = nullptr;  // begin_step points it at the field's values
  OwnedParticles owned;
  // [m^2/s] largest kinematic viscosity of the owned materials, for the viscous time-step limit:
  // 0 with implicit viscosity, which has none.
  Real max_viscosity = 0;
  // The time-step limits of the owned materials' viscosity and surface tension.
  FluidForceLimits force_limits() const {
    return {max_viscosity, table.max_sigma_over_density, Real(table.viscosity_operator.stiffness)};
  }
  FieldHandle<Real> density_field, pressure_field;  // the exported fields every fluid solver writes

  // Per-step buffers, rewritten every step (so they need no reordering with the particles).
  std::vector<Vec3> fluid_gradient;      // grad W_ij per fluid-list slot
  std::vector<Vec3> boundary_gradient;   // per particle: sum_b V_b grad W_ib
  std::vector<Vec3> other_acceleration;  // per particle: gravity + shared viscosity
  // Per particle: the solver's pressure term. A field, because neighbours read it (IISPH), and
  // ghosts on other ranks must carry it (particle_domain.h); begin_step points at its values.
  FieldHandle<Vec3> pressure_acceleration_field;
  Vec3* pressure_acceleration = nullptr;
  // Per particle, with surface tension on: Akinci's normals (surface_forces.h). A field, because
  // neighbours read it and ghosts on other ranks must carry it.
  FieldHandle<Vec3> surface_normal_field;
  Vec3* surface_normal = nullptr;  // begin_step points it at the field's values
  // Per particle, with the continuum surface force: its fitted curvatures and their weights
  // (continuum_surface_force.h), fields for the same reason; begin_step points them.
  Real* surface_curvature = nullptr;
  Real* surface_curvature_weight = nullptr;
  Vec3* surface_smoothed_normal = nullptr;
  bool surface_tension() const { return table.surface_model != SurfaceTensionModel::None; }
  // With implicit viscosity (implicit_viscosity.h): its per-particle fields, the last step's
  // viscous acceleration (the warm start, kept across steps and in checkpoints) and the last
  // solve's statistics.
  ImplicitViscosityArrays viscosity_arrays{};  // begin_step points them at the fields
  ImplicitViscosityStats viscosity_stats;
  bool implicit_viscosity() const { return table.implicit_viscosity; }
  // A solver's statistics with the last viscous solve's iterations (SolverStats).
  SolverStats with_viscosity(SolverStats s) const {
    if (implicit_viscosity()) s.viscosity_iterations = viscosity_stats.iterations;
    return s;
  }

  // Creates the exported fields `density` and `pressure`, requests the neighbour lists and loads
  // the constants of `materials`.
  void prepare(World& world, const std::vector<MaterialId>& materials);
  // Rebuilds the owned list, sizes the buffers for this step's lists; the current state's view.
  FluidView begin_step(World& world);
  // The density field of the owned particles at the current positions, nothing else: the initial
  // state's (Solver::initialize_fields), which frame 0 shows.
  void initial_density(World& world);
  // Writes density (field `density`), the kernel gradients and other_acceleration.
  // With f.wall_pressure, also the hydrostatic part of the wall pressure (boundary_pressure.h),
  // and its reactions on static and kinematic bodies (boundary_reactions.h).
  // With implicit viscosity, solves it for a step of dt (run_non_pressure_stages throws
  // ConvergenceError when the solve does not reach its tolerance within its cap).
  void shared_forces(World& world, const FluidView& f, Real* density, Real dt);
  // Adds the reactions of the owned particles' boundary forces to the world's coupling array
  // CouplingArray::BoundaryForce, when the world has body particles. `pressure_factor` is P_i of
  // boundary_reactions.h (a value struct, fluid_stages.h); `pressure_gradient` the gradient of the
  // solver's pressure term.
  template <class PressureFactor, class PressureGradient = CubicSplineGradient>
  void add_reactions(World& world, const FluidView& f, const Real* density,
                     const PressureFactor& pressure_factor,
                     const PressureGradient& pressure_gradient) const {
    if (reaction_list < 0) return;
    std::vector<Vec3>& force = world.coupling()[CouplingArray::BoundaryForce];
    run_boundary_reactions(world.executor(), force.size(), f,
                           view_of(world.neighbours(reaction_list)), density, owned.materials(),
                           pressure_factor, pressure_gradient, force.data());
  }
  template <class PressureFactor>
  void add_reactions(World& world, const FluidView& f, const Real* density,
                     const PressureFactor& pressure_factor) const {
    add_reactions(world, f, density, pressure_factor, CubicSplineGradient{f.kernel});
  }
  // x_star = x + v dt for every particle this solver does not move, before a solver evaluates
  // anything at predicted positions: bodies move on, walls stay put, so an approaching body is
  // not seen a step late.
  void predict_unowned(const World& world, const FluidView& f, Vec3* x_star, Real dt) const;
  // Symplectic Euler over the owned particles with other_acceleration + pressure_acceleration.
  void integrate(World& world, Real dt) const;
};

}  // namespace upf
