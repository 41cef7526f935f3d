// The per-particle stages every fluid solver shares (FluidSolverState runs them). Each is a plain
// struct of views with a UPF_HD operator()(i) that writes only particle i (DESIGN.md, "Stages,
// executors and backends"). C++17: nvcc compiles these too (fluid_cuda_check.cu).
#pragma once

#include "framework/core/errors.h"
#include "solvers/fluid/boundary_pressure.h"
#include "solvers/fluid/boundary_reactions.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/implicit_viscosity.h"
#include "solvers/fluid/owned_particles.h"
#include "solvers/fluid/surface_forces.h"
#include "solvers/fluid/wall_velocity.h"

namespace upf {

// Scratch fields every fluid solver declares (FluidSolverState::prepare) and the device pipeline
// binds: ghosts and periodic images carry them, and neighbours read the normals.
inline constexpr const char* kPressureAccelerationField = "fluid.pressure_acceleration";
inline constexpr const char* kSurfaceNormalField = "fluid.surface_normal";
// The continuum surface force's (continuum_surface_force.h): neighbours read them too.
inline constexpr const char* kSurfaceCurvatureField = "fluid.surface_curvature";
inline constexpr const char* kSurfaceCurvatureWeightField = "fluid.surface_curvature_weight";
inline constexpr const char* kSurfaceSmoothedNormalField = "fluid.surface_smoothed_normal";

// Density and kernel gradients at the current positions (fluid_forces.h), and with
// `surface_normal` not null Akinci's surface normals, which the surface tension of i's neighbours
// reads (surface_forces.h).
struct DensityAndGradientsStage {
  FluidView f;
  FluidGradients fluid_gradient;  // per fluid-list slot
  Vec3* boundary_gradient;        // per particle
  Real* density;
  Vec3* surface_normal = nullptr;  // per particle
  UPF_HD void operator()(std::uint32_t i) const {
    density[i] = density_and_gradients(f, fluid_gradient, boundary_gradient[i], i,
                                       surface_normal ? surface_normal + i : nullptr);
  }
};

// a_other = g + the shared viscosity (fluid_forces.h) + surface tension and adhesion (with
// f.surface on; surface_forces.h) + the wall pressure's hydrostatic part (boundary_pressure.h;
// with f.wall_pressure only).
struct GravityAndViscosityStage {
  FluidView f;
  const Real* density;
  FluidGradients fluid_gradient;
  const Real* pressure;
  Vec3 gravity;
  Vec3* a_other;
  UPF_HD void operator()(std::uint32_t i) const {
    Vec3 a = gravity + viscosity_acceleration(f, density, fluid_gradient, i);
    if (f.surface.on()) a += surface_acceleration(f, density, i);
    if (f.wall_pressure) a += boundary_hydrostatic_acceleration(f, pressure, gravity, i);
    a_other[i] = a;
  }
};

// a += F / m: the force other materials put on particle i (CouplingArray::LiquidForce).
struct AddForceOverMassStage {
  const Vec3* force;
  const Real* mass;
  Vec3* acceleration;
  UPF_HD void operator()(std::uint32_t i) const { acceleration[i] += force[i] / mass[i]; }
};

// x* = x + v dt for the particles a solver does not move (FluidSolverState::predict_unowned).
struct PredictUnownedStage {
  FluidView f;
  OwnedMaterials owns;
  Real dt;
  Vec3* x_star;
  UPF_HD void operator()(std::uint32_t i) const {
    if (f.type[i] != ParticleType::Liquid || !owns(f.material[i])) x_star[i] = f.x[i] + f.v[i] * dt;
  }
};

// Symplectic Euler: v += (a_other + a_pressure) dt, then x += v dt.
struct SymplecticEulerStage {
  const Vec3* a_other;
  const Vec3* a_pressure;
  Real dt;
  Vec3* v;
  Vec3* x;
  UPF_HD void operator()(std::uint32_t i) const {
    v[i] += (a_other[i] + a_pressure[i]) * dt;
    x[i] += v[i] * dt;
  }
};

// Zeroes a scalar and a vector per particle (pressures and pressure accelerations at step start).
struct ClearPressureStage {
  Real* pressure;
  Vec3* a_pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    pressure[i] = 0;
    a_pressure[i] = Vec3{};
  }
};

// The relative compression (rho_i - rho0_i) / rho0_i, clamped below at 0 (compression_stats.h).
struct CompressionValue {
  const Real* rest_density;  // per material
  const MaterialId* material;
  const Real* density;
  UPF_HD Real operator()(std::uint32_t i) const {
    const Real rho0 = rest_density[material[i]];
    const Real e = (density[i] - rho0) / rho0;
    return e > 0 ? e : Real(0);
  }
};

// The non-pressure part every fluid solver's step starts with, for any executor (the CPU's, or
// the device pipeline's): density and kernel gradients at the current positions, with the surface
// normals when f.surface is on (into `surface_normal`, the array f.surface.normal reads), the
// continuum surface force's smoothed normals and fitted curvatures when it is the model, then
// a_other = g + viscosity + surface forces, plus F / m from other materials when `liquid_force` is
// not null; with `viscous.arrays` (implicit viscosity) the viscosity comes last, solved at the
// end-of-step velocities these accelerations give (implicit_viscosity.h): its statistics are
// returned, and a solve that does not converge throws ConvergenceError.
struct NonPressureArrays {
  FluidGradients fluid_gradient;
  Vec3* boundary_gradient;
  Vec3* other_acceleration;
  Real* density;
  const Vec3* liquid_force;  // CouplingArray::LiquidForce, or null
  const Real* pressure;      // at the step's start: the wall pressure's hydrostatic part
  Vec3* surface_normal;      // with f.surface on: per particle, f.surface.normal's array
  // With wall friction: boundary -> liquid lists, and the array f.wall_velocity reads (written
  // here, over all `all` particles, first: wall_velocity.h).
  NeighbourView liquid_of_boundary{};
  Vec3* wall_velocity = nullptr;
  std::size_t all = 0;
  // With f.body_wall_floor (the wall pressure beside static or kinematic bodies): the reaction
  // lists (body particles -> liquid), the reactions' array and the solver's materials; the
  // hydrostatic part's reactions are added here (boundary_reactions.h).
  NeighbourView liquid_of_body{};
  Vec3* boundary_force = nullptr;
  OwnedMaterials owns{};
  // With the continuum surface force: per particle, f.surface.curvature's, curvature_weight's and
  // smoothed_normal's arrays, written after the normals.
  Real* surface_curvature = nullptr;
  Real* surface_curvature_weight = nullptr;
  Vec3* surface_smoothed_normal = nullptr;
};

template <class Executor>
ImplicitViscosityStats run_non_pressure_stages(const Executor& exec, ParticleRange owned,
                                               const FluidView& f, const NonPressureArrays& a,
                                               const Vec3& gravity,
                                               const ImplicitViscosityStep& viscous = {}) {
  if (a.wall_velocity)
    exec.run(all_particles(a.all), WallVelocityStage{f, a.liquid_of_boundary, a.wall_velocity});
  exec.run(owned, DensityAndGradientsStage{f, a.fluid_gradient, a.boundary_gradient, a.density,
                                           f.surface.on() ? a.surface_normal : nullptr});
  if (f.surface.model == SurfaceTensionModel::ContinuumSurfaceForce) {
    exec.run(owned, SmoothedNormalStage{f, a.surface_smoothed_normal});
    exec.run(owned, FittedCurvatureStage{f, a.surface_smoothed_normal, a.surface_curvature,
                                         a.surface_curvature_weight});
  }
  exec.run(owned, GravityAndViscosityStage{f, a.density, a.fluid_gradient, a.pressure, gravity,
                                           a.other_acceleration});
  if (a.liquid_force)
    exec.run(owned, AddForceOverMassStage{a.liquid_force, f.mass, a.other_acceleration});
  if (f.body_wall_floor && a.boundary_force)
    run_body_wall_hydrostatic_reactions(exec, a.all, f, a.liquid_of_body, a.owns, a.pressure,
                                        gravity, a.boundary_force);
  if (!viscous.arrays) return {};
  const ImplicitViscosityStats stats = solve_implicit_viscosity(
      exec, owned, viscous.all, f, viscous.owns, a.density, a.fluid_gradient, a.other_acceleration,
      *viscous.arrays, viscous.settings, viscous.dt);
  if (!stats.converged) throw ConvergenceError(implicit_viscosity_failure(stats, viscous.settings));
  return stats;
}

}  // namespace upf
