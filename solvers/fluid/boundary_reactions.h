// The reactions of fluid forces on rigid boundary particles (Akinci et al. 2012, "Versatile
// rigid-fluid coupling for incompressible SPH", ACM TOG 31(4), eq. 11 and 13): the force a
// boundary particle b exerts on fluid particle i is put, with the opposite sign, on b.
//
// Every fluid solver here writes its boundary pressure acceleration as
//   a_i = -rho0_i P_i sum_b V_b grad W_ib,
// with P_i its own pressure factor (PCISPH p_i/rho0^2, WCSPH p_i/rho_i^2, SPH p_i/(2 rho_i^2)),
// the shared boundary viscosity of fluid_forces.h and Akinci et al. 2013's adhesion
// (surface_forces.h). So the reaction on b is
//   F_b = sum_i m_i [ rho0_i P_i V_b grad W_ib
//                     - F nu_b,i rho0_i V_b / rho_i (v_ib . x_ib) / (|x_ib|^2 + 0.01 H^2) grad
//                     W_ib
//                     + beta rho0_i V_b A(|x_ib|) x_ib / |x_ib| ]
// gathered over b's fluid neighbours: no scatter, no atomics, the same bits for any thread
// count. The pairs cancel exactly up to rounding, so fluid and bodies together conserve momentum.
//
// The frozen particles of static and kinematic bodies take reactions too, which are their
// reported fluid force (nothing moves them). With the wall pressure (boundary_pressure.h) a
// frozen particle also pushes with the mirrored factor P_b of each neighbour and with the
// hydrostatic part of p_b; their reactions are
//   F_b += sum_i m_i [ rho0_i P_b,i V_b grad W_ib + V_b dp_b,i / rho0_i grad W_ib ],
// the second at the step's start pressures, before the pressure solve. P_b,i and pbar_i (dp's
// floor) average over i's fluid neighbours, so they are stored per liquid particle first: across
// ranks a ghost's value then comes from its owner, not from its incomplete lists.
#pragma once

#include <cstddef>

#include "framework/executors/particle_range.h"
#include "solvers/fluid/boundary_pressure.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"
#include "solvers/fluid/surface_forces.h"
#include "solvers/fluid/wall_velocity.h"

namespace upf {

// Whether frozen body particles take the wall pressure's reactions: with the wall pressure, where
// the reaction lists (`reaction_query`, body_reaction_query) hold frozen body particles.
inline bool body_wall_reactions(bool wall_pressure, TypeMask reaction_query) {
  return wall_pressure && in_mask(reaction_query, ParticleType::Frozen);
}

// The per-particle scratch fields of FluidView::body_wall_factor and body_wall_floor, declared
// where body_wall_reactions holds.
inline constexpr const char* kBodyWallFactorField = "fluid.body_wall_factor";
inline constexpr const char* kBodyWallFloorField = "fluid.body_wall_floor";

// The reaction on body particle b, gathered over `fluid_of_boundary` (for each body particle,
// its liquid neighbours); only those of an owned material count (the solver's own particles).
// `pressure_factor(i)` is P_i (fluid_stages.h); `pressure_gradient(r)` is the kernel gradient the
// solver's pressure term uses. Adds to force[b].
template <class PressureFactor, class PressureGradient>
struct BoundaryReactionStage {
  FluidView f;
  NeighbourView fluid_of_boundary;
  const Real* density;
  OwnedMaterials owns;
  PressureFactor pressure_factor;
  PressureGradient pressure_gradient;
  Vec3* force;

  UPF_HD void operator()(std::uint32_t b) const {
    const std::uint32_t begin = fluid_of_boundary.offsets[b];
    const std::uint32_t end = fluid_of_boundary.offsets[b + 1];
    if (begin == end) return;
    const Real h2 = f.kernel.support_radius() * f.kernel.support_radius();
    const Vec3 xb = f.x[b];
    const Vec3 vb = viscous_wall_velocity(f, b);
    const Real vol = f.boundary_volume[b];
    const Real* wall_factor = f.type[b] == ParticleType::Frozen ? f.body_wall_factor : nullptr;
    Vec3 sum{};
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = fluid_of_boundary.indices[k];
      const MaterialId m = f.material[i];
      if (!owns(m)) continue;
      const Vec3 xib = f.x[i] - xb;
      const Real rho0 = f.rest_density[m];
      Vec3 pair = pressure_gradient(xib) * (rho0 * pressure_factor(i) * vol);
      if (wall_factor) pair += f.kernel.gradient(xib) * (rho0 * wall_factor[i] * vol);
      const Real nub = f.boundary_viscosity[m];
      if (nub > 0) {
        // With implicit viscosity, at the velocities its solve found (implicit_viscosity.h).
        const Vec3 vi = f.solved_velocity ? f.solved_velocity[i] : f.v[i];
        const Real vx = dot(vi - vb, xib);
        pair -= f.kernel.gradient(xib) * (f.viscosity_factor * nub * rho0 * vol / density[i] * vx /
                                          (squared_norm(xib) + Real(0.01) * h2));
      }
      sum += pair * f.mass[i];
      if (f.surface.has_adhesion) sum += akinci_adhesion_reaction(f, i, b);
    }
    force[b] += sum;
  }
};

// Whether particle i is owned liquid beside a frozen body particle: the only ones whose factors
// the reactions read (the Shepard averages cost a pass over i's fluid neighbours).
UPF_HD inline bool beside_a_frozen_body(const FluidView& f, OwnedMaterials owns, std::uint32_t i) {
  if (f.type[i] != ParticleType::Liquid || !owns(f.material[i])) return false;
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    if (f.type[b] == ParticleType::Frozen && f.body[b] != kNoBody) return true;
  }
  return false;
}

// Per owned liquid particle i beside a frozen body, the mirrored factor of its frozen neighbours
// (P_b of boundary_pressure.h) from the solver's final pressure factors.
template <class PressureFactor>
struct BodyWallFactorStage {
  FluidView f;
  OwnedMaterials owns;
  PressureFactor pressure_factor;
  UPF_HD void operator()(std::uint32_t i) const {
    if (!beside_a_frozen_body(f, owns, i)) return;
    f.body_wall_factor[i] = mirrored_pressure_factor(f, pressure_factor, i);
  }
};

// Per owned liquid particle i beside a frozen body, pbar_i at the step's start (the floor of the
// hydrostatic part).
struct BodyWallFloorStage {
  FluidView f;
  OwnedMaterials owns;
  const Real* pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    if (!beside_a_frozen_body(f, owns, i)) return;
    f.body_wall_floor[i] = mirrored_pressure_factor(f, PressureArray{pressure}, i);
  }
};

// The reaction of the wall pressure's hydrostatic part (boundary_hydrostatic_acceleration) on
// frozen body particle b, added to force[b].
struct BodyWallHydrostaticReactionStage {
  FluidView f;
  NeighbourView fluid_of_boundary;
  OwnedMaterials owns;
  Vec3 gravity;
  Vec3* force;
  UPF_HD void operator()(std::uint32_t b) const {
    if (f.type[b] != ParticleType::Frozen) return;
    const std::uint32_t begin = fluid_of_boundary.offsets[b];
    const std::uint32_t end = fluid_of_boundary.offsets[b + 1];
    if (begin == end) return;
    const Vec3 xb = f.x[b];
    Vec3 sum{};
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = fluid_of_boundary.indices[k];
      const MaterialId m = f.material[i];
      if (!owns(m)) continue;
      const Real rho0 = f.rest_density[m];
      const Real extra = rho0 * dot(gravity, xb - f.x[i]);
      const Real floor = -f.body_wall_floor[i];
      const Real dp = extra > floor ? extra : floor;
      sum += f.kernel.gradient(f.x[i] - xb) * (f.mass[i] * dp / rho0);
    }
    force[b] += sum * f.boundary_volume[b];
  }
};

// The hydrostatic part's reactions, at the step's start pressures `pressure`: the shared
// non-pressure stages run it (fluid_stages.h) when f.body_wall_floor is set.
template <class Executor>
void run_body_wall_hydrostatic_reactions(const Executor& exec, std::size_t n, const FluidView& f,
                                         NeighbourView fluid_of_boundary, OwnedMaterials owns,
                                         const Real* pressure, const Vec3& gravity, Vec3* force) {
  exec.run(all_particles(n), BodyWallFloorStage{f, owns, pressure});
  exec.run(all_particles(n),
           BodyWallHydrostaticReactionStage{f, fluid_of_boundary, owns, gravity, force});
}

// The cubic spline gradient, which every solver's pressure term uses by default.
struct CubicSplineGradient {
  CubicSplineKernel kernel;
  UPF_HD Vec3 operator()(const Vec3& r) const { return kernel.gradient(r); }
};

// The stage over all n particles (only body particles have entries in `fluid_of_boundary`), on any
// executor: the CPU's (FluidSolverState::add_reactions) or a device pipeline's.
template <class Executor, class PressureFactor, class PressureGradient>
void run_boundary_reactions(const Executor& exec, std::size_t n, const FluidView& f,
                            NeighbourView fluid_of_boundary, const Real* density,
                            OwnedMaterials owns, const PressureFactor& pressure_factor,
                            const PressureGradient& pressure_gradient, Vec3* force) {
  if (f.body_wall_factor)
    exec.run(all_particles(n), BodyWallFactorStage<PressureFactor>{f, owns, pressure_factor});
  exec.run(all_particles(n),
           BoundaryReactionStage<PressureFactor, PressureGradient>{
               f, fluid_of_boundary, density, owns, pressure_factor, pressure_gradient, force});
}

}  // namespace upf
