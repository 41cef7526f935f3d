// What every fluid solver shares: a raw view of the particle arrays, the neighbour lists
// (fluid -> fluid, fluid -> boundary) and the per-material constants. Per-particle functions take
// this view by value so the same source runs in OpenMP loops and, later, in CUDA kernels.
#pragma once

#include <vector>

#include "framework/core/particle_type.h"
#include "framework/kernels/cubic_spline.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"
#include "solvers/fluid/surface_force_view.h"
#include "solvers/fluid/viscosity_operator.h"

namespace upf {

class World;

struct FluidView {
  const Vec3* x = nullptr;
  const Vec3* v = nullptr;
  const Real* mass = nullptr;
  const ParticleType* type = nullptr;
  const MaterialId* material = nullptr;
  const Real* boundary_volume = nullptr;
  const Real* rest_density = nullptr;        // per material
  const Real* viscosity = nullptr;           // per material, kinematic [m^2/s]
  const Real* boundary_viscosity = nullptr;  // per material, kinematic [m^2/s]
  Real viscosity_factor = 10;                // F of the Laplacian (viscosity_operator.h)
  NeighbourView fluid;                       // fluid -> fluid
  NeighbourView boundary;                    // fluid -> frozen and rigid
  CubicSplineKernel kernel;
  // Walls and bodies carry the pressure of boundary_pressure.h; else Akinci et al.'s term alone.
  bool wall_pressure = false;
  // The liquids differ in rest density: density and pressure take the number-density forms of
  // Solenthaler & Pajarola 2008 (density_contrast.h).
  bool density_contrast = false;
  SurfaceForceView surface;  // surface tension and adhesion (surface_forces.h); off by default
  // With implicit viscosity (implicit_viscosity.h): the velocities its solve found, which the
  // viscous reactions on bodies use; the explicit viscosity of fluid_forces.h is then off. Null:
  // explicit viscosity.
  const Vec3* solved_velocity = nullptr;
  // With wall friction (a liquid's boundary_viscosity > 0): every boundary particle's velocity in
  // the viscous sums, extrapolated from the liquid (wall_velocity.h). Null: their own.
  const Vec3* wall_velocity = nullptr;
  // With free-slip boundaries (a frozen or rigid material's free_slip): every particle's wall
  // normal, zero where no-slip (framework/boundary/slip_normal.h). Null: all no-slip.
  const Vec3* slip_normal = nullptr;
  // With the wall pressure and static or kinematic bodies (whose frozen particles take reactions;
  // boundary_reactions.h): per particle, arrays the reaction stages fill for the owned liquid, the
  // frozen neighbours' mirrored factor P_b at the reactions and the Shepard pressure pbar_i at the
  // step's start (boundary_pressure.h), and the particles' body ids, to find the liquid beside
  // such bodies. Null: no such bodies.
  Real* body_wall_factor = nullptr;
  Real* body_wall_floor = nullptr;
  const BodyId* body = nullptr;
};

// The kernel gradients grad W_ij of a step's fluid pairs, by fluid-list slot k of particle i:
// stored once by density_and_gradients (12 B a pair), or, with nothing stored, recomputed where
// they are used, from the same positions by the same function, so with the same bits (positions
// do not move between the shared forces and the integration). The CPU path stores them; the
// device pipeline recomputes them, trading arithmetic for memory and memory traffic.
struct FluidGradients {
  Vec3* stored = nullptr;
  FluidGradients() = default;
  UPF_HD FluidGradients(Vec3* gradients) : stored(gradients) {}  // NOLINT: a pointer is a store
  UPF_HD Vec3 at(const FluidView& f, std::uint32_t i, std::uint32_t k) const {
    if (stored) return stored[k];
    Vec3 g;
    (void)f.kernel.value_and_gradient(f.x[i] - f.x[f.fluid.indices[k]], g);
    return g;
  }
};

// Per-material constants, copied once in prepare() into arrays a view can point at.
// Surface tension: the model the liquids name (one per solver; the scene reader refuses two), the
// per-material coefficient that model uses for each liquid's `surface_tension` sigma [N/m], and
// Akinci's beta per (liquid, boundary material) pair from the liquids' `adhesion`.
struct FluidMaterialTable {
  std::vector<Real> rest_density, viscosity, boundary_viscosity;
  bool density_contrast = false;  // the world's liquids differ in rest density (density_contrast.h)
  ViscosityOperator viscosity_operator;  // the Laplacian's F and stiffness at this spacing
  SurfaceTensionModel surface_model = SurfaceTensionModel::None;
  std::vector<Real> cohesion, adhesion;
  bool has_adhesion = false;
  Real max_sigma_over_density = 0;  // [m^3/s^2] the capillary time-step limit's largest sigma/rho0
  // Implicit viscosity (implicit_viscosity.h): whether the solver's liquids ask for it (the scene
  // reader made them agree), and the strictest tolerance and largest iteration cap among them.
  bool implicit_viscosity = false;
  double viscosity_tolerance = 1e-3;
  int viscosity_max_iterations = 100;
  // Reads the constants of every material; the surface model of `materials` (the solver's).
  void load(const World& world, const std::vector<MaterialId>& materials);
};

// Neighbour-list handles for the lists every fluid solver needs.
struct FluidNeighbourHandles {
  int fluid = -1, boundary = -1;
  void request(World& world);
};

FluidView make_fluid_view(const World& world, const FluidMaterialTable& materials,
                          const FluidNeighbourHandles& lists);

}  // namespace upf
