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
// 0.125 H^2 / nu (Morris et al. 1997), or no limit without viscosity.
Real viscous_time_step(const WorldSettings& s, Real max_viscosity) {
  if (max_viscosity <= 0) return std::numeric_limits<Real>::max();
  const Real h = s.support_radius();
  return Real(0.125) * h * h / max_viscosity;
}

Real max_liquid_speed(const World& world) {
  return std::sqrt(world.max_liquid_speed_squared());
}
}  // namespace

Real fluid_cfl_time_step(const World& world, Real max_viscosity, Real reference_speed) {
  const auto& s = world.settings();
  Real dt = std::numeric_limits<Real>::max();
  const Real vmax = std::max(reference_speed, max_liquid_speed(world));
  if (vmax > 0) dt = Real(s.time.cfl) * s.spacing / vmax;
  return std::min(dt, viscous_time_step(s, max_viscosity));
}

Real sound_speed_time_step(const World& world, Real cfl, Real sound_speed, Real max_viscosity) {
  const auto& s = world.settings();
  Real dt = std::numeric_limits<Real>::max();
  const Real signal_speed = sound_speed + max_liquid_speed(world);
  if (signal_speed > 0) dt = cfl * s.spacing / signal_speed;
  return std::min(dt, viscous_time_step(s, max_viscosity));
}

}  // namespace upf
