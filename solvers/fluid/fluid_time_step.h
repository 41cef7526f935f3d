// The time-step limits every fluid solver shares: the CFL condition dt <= cfl * spacing / |v|max
// (Courant, Friedrichs & Lewy 1928, in the particle form of Monaghan 1992) and the viscous limit
// dt <= 0.125 H^2 / nu (Monaghan 1992 / Morris et al. 1997).
#pragma once

#include "framework/core/real.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/particles/particles.h"

namespace upf {

class World;

// Largest squared speed of liquid particles: exact, so the same for any thread count.
Real max_liquid_speed_squared(const Particles& particles, const CpuExecutor& exec);

Real fluid_cfl_time_step(const World& world, Real max_viscosity);

}  // namespace upf
