// The time-step limits every fluid solver shares: the CFL condition
//   dt <= cfl * spacing / max(|v|max, v_ref)
// (Courant, Friedrichs & Lewy 1928, in the particle form of Monaghan 1992), the viscous limit
// dt <= 1 / (nu stiffness) of viscosity_operator.h (half the stable step of the lattice's
// Laplacian, 0.070 s^2 / nu at H = 2 s) and, with surface tension, the capillary limit
// dt <= 0.15 sqrt(rho0 s^3 / (2 pi sigma)) (the form of Brackbill, Kothe & Zemach 1992; Adami, Hu
// & Adams 2010 take 0.25 for their continuum force, under which a free drop of water with Akinci's
// cohesion flew apart with PCISPH at nu <= 1e-4: docs/surface-tension.md), s the particle spacing.
// v_ref = sqrt(2 g H), H the height of the liquid along gravity, is the speed the flow can reach by
// falling: a scene at rest still gets a step that resolves the motion it is about to have (without
// it, PCISPH at rest ran at dt_max and blew up at the tank corners: 4 ms at 2 cm spacing, 2 ms
// at 1.25 cm).
#pragma once

#include "framework/core/real.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/particles/particles.h"

namespace upf {

class World;

// The limits of the forces beside the pressure: the largest kinematic viscosity [m^2/s] and the
// largest sigma / rho0 [m^3/s^2] of the solver's liquids.
struct FluidForceLimits {
  Real max_viscosity = 0;  // 0 with implicit viscosity, which does not limit the step
  Real max_sigma_over_density = 0;
  Real viscosity_stiffness = 0;  // [1/m^2] ViscosityOperator::stiffness
};

Real fluid_cfl_time_step(const World& world, const FluidForceLimits& limits, Real reference_speed);

// For solvers whose pressure waves travel at a speed of sound c (SPH's sqrt(k), WCSPH's c):
//   dt <= cfl * spacing / (c + |v|max)
// and the force limits above.
Real sound_speed_time_step(const World& world, Real cfl, Real sound_speed,
                           const FluidForceLimits& limits);

// sqrt(2 |g| H) with H the extent of the liquid along gravity (0 without gravity or liquid).
Real free_fall_speed(const World& world);

}  // namespace upf
