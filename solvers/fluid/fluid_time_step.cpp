#include "solvers/fluid/fluid_time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/world/world.h"

namespace upf {

Real free_fall_speed(const World& world) {
  const Vec3 g = world.settings().gravity;
  const Real g_norm = norm(g);
  if (g_norm <= 0) return 0;
  const Vec3 down = g / g_norm;
  const Particles& p = world.particles();
  Real lo = std::numeric_limits<Real>::max(), hi = std::numeric_limits<Real>::lowest();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const Real d = dot(p.position[i], down);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return hi > lo ? std::sqrt(Real(2) * g_norm * (hi - lo)) : Real(0);
}

namespace {
// 1 / (nu stiffness) (viscosity_operator.h) and 0.15 sqrt(s^3 / (2 pi sigma / rho0)) (the capillary
// limit's form, Brackbill et al. 1992, with a factor measured for Akinci's cohesion: PCISPH's free
// drop flies apart at 0.25), or no limit without viscosity and surface tension.
Real force_time_step(const WorldSettings& s, const FluidForceLimits& limits) {
  Real dt = std::numeric_limits<Real>::max();
  if (limits.max_viscosity > 0 && limits.viscosity_stiffness > 0)
    dt = Real(1) / (limits.max_viscosity * limits.viscosity_stiffness);
  if (limits.max_sigma_over_density > 0) {
    constexpr Real kTwoPi = Real(6.28318530717958647692);
    const Real spacing_cubed = s.spacing * s.spacing * s.spacing;
    dt = std::min(dt,
                  Real(0.15) * std::sqrt(spacing_cubed / (kTwoPi * limits.max_sigma_over_density)));
  }
  return dt;
}

Real max_liquid_speed(const World& world) {
  return std::sqrt(world.max_liquid_speed_squared());
}
}  // namespace

Real fluid_cfl_time_step(const World& world, const FluidForceLimits& limits, Real reference_speed) {
  const auto& s = world.settings();
  Real dt = std::numeric_limits<Real>::max();
  const Real vmax = std::max(reference_speed, max_liquid_speed(world));
  if (vmax > 0) dt = Real(s.time.cfl) * s.spacing / vmax;
  return std::min(dt, force_time_step(s, limits));
}

Real sound_speed_time_step(const World& world, Real cfl, Real sound_speed,
                           const FluidForceLimits& limits) {
  const auto& s = world.settings();
  Real dt = std::numeric_limits<Real>::max();
  const Real signal_speed = sound_speed + max_liquid_speed(world);
  if (signal_speed > 0) dt = cfl * s.spacing / signal_speed;
  return std::min(dt, force_time_step(s, limits));
}

}  // namespace upf
