// Measurements the tank scenes of the physics tests share, whatever the solver: where the liquid
// is, and the state of water settled at rest (hydrostatic tank). Each test asserts its own bounds.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "scene_helpers.h"

namespace upf::testing {

// The first liquid particle (by index) outside `box` grown by `margin`, if any: with a margin of
// half a spacing, such a particle has left the tank through its first wall layer.
inline std::optional<std::size_t> liquid_outside(const Particles& p, const Box& box,
                                                 double margin) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const Vec3& x = p.position[i];
    for (int a = 0; a < 3; ++a)
      if (!(double(x[a]) > box.min[a] - margin && double(x[a]) < box.max[a] + margin)) return i;
  }
  return std::nullopt;
}

// A flow in a tank run to `end`: what the tests of violent flows (dam breaks) check.
struct TankRun {
  std::uint64_t steps = 0;
  double mean_iterations = 0;
  double mean_avg_density_error = 0, max_avg_density_error = 0;  // the solver's, over the steps
  std::size_t liquid_before = 0, liquid_after = 0;
  std::optional<std::size_t> not_finite;  // a particle whose position or velocity is not finite
  std::optional<std::size_t> outside;     // a liquid particle that left the tank
  double front = 0;                       // [m] the largest x of the liquid at the end
};

inline TankRun run_in_tank(TestWorld& tw, double end) {
  World& w = *tw.world;
  const Particles& p = w.particles();
  TankRun r;
  r.liquid_before = p.count(ParticleType::Liquid);
  double iterations = 0, error_sum = 0;
  while (w.time() < end - 1e-12) {
    w.step(w.next_time_step_until(end));
    const SolverStats& s = w.last_step().solver;
    iterations += s.iterations;
    error_sum += s.avg_density_error;
    r.max_avg_density_error = std::max(r.max_avg_density_error, s.avg_density_error);
    ++r.steps;
  }
  r.mean_iterations = iterations / double(r.steps);
  r.mean_avg_density_error = error_sum / double(r.steps);
  r.liquid_after = p.count(ParticleType::Liquid);
  for (std::size_t i = 0; i < p.size() && !r.not_finite; ++i)
    if (!is_finite(p.position[i]) || !is_finite(p.velocity[i])) r.not_finite = i;
  r.outside = liquid_outside(p, tw.scene.containers.front().box, 0.5 * tw.scene.world.spacing);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Liquid) r.front = std::max(r.front, double(p.position[i].x));
  return r;
}

// Water settled in a tank (the scene's first container, gravity along -y, rest density rho0).
struct TankAtRest {
  double column = 0;   // [m] the height of the scene's first fluid block
  double surface = 0;  // [m] the top liquid particle + half a spacing
  double v_rms = 0;    // [m/s]
  // Compression (rho - rho0)/rho0 of the field `density` at the end: the average of max(0, e),
  // the largest away from the tank's edges, the largest within a support radius of two walls
  // (edges and corners, where it is largest).
  double avg_compression = 0, max_compression = 0, max_compression_edges = 0;
  // (depth, pressure) per horizontal slab one spacing thick, every support radius from two
  // support radii below the surface to two above the floor (of the column), at least two support
  // radii from the side walls, with the
  // field `pressure` averaged over time per particle; NaN for an empty slab.
  std::vector<std::pair<double, double>> pressure_by_depth;
  std::optional<std::size_t> outside;  // a liquid particle that left the tank
};

// Runs until `settle_time`, then averages the pressure over `average_time`, sampled every
// 10 ms: pressures are re-solved every step and flicker, as a sensor's reading would be averaged.
inline TankAtRest measure_tank_at_rest(TestWorld& tw, double rho0, double settle_time,
                                       double average_time) {
  tw.run_until(settle_time);
  const World& w = *tw.world;
  const Particles& p = w.particles();
  const double end = settle_time + average_time;
  std::map<ParticleId, double> pressure_sum;
  int samples = 0;
  while (w.time() < end - 1e-12) {
    tw.run_until(std::min(w.time() + 0.01, end));
    const auto& pr = *p.find_scalar("pressure");
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Liquid) pressure_sum[p.id[i]] += double(pr[i]);
    ++samples;
  }

  TankAtRest r;
  const Box& tank = tw.scene.containers.front().box;
  const double h = tw.scene.world.spacing, support = tw.scene.world.support_radius();
  const auto& density = *p.find_scalar("density");
  auto side_walls_within = [&](const Vec3& x, double d) {
    return int(x.x < tank.min[0] + d || x.x > tank.max[0] - d) +
           int(x.z < tank.min[2] + d || x.z > tank.max[2] - d);
  };
  auto walls_within = [&](const Vec3& x, double d) {
    return side_walls_within(x, d) + int(x.y < tank.min[1] + d);
  };
  double top = tank.min[1], v2 = 0, error_sum = 0;
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const double e = (double(density[i]) - rho0) / rho0;
    error_sum += std::max(0.0, e);
    double& max_error =
        walls_within(p.position[i], support) >= 2 ? r.max_compression_edges : r.max_compression;
    max_error = std::max(max_error, e);
    top = std::max(top, double(p.position[i].y));
    v2 += double(squared_norm(p.velocity[i]));
    ++fluid;
  }
  r.avg_compression = error_sum / double(fluid);
  r.v_rms = std::sqrt(v2 / double(fluid));
  r.surface = top + 0.5 * h;

  const Box& block = tw.scene.fluid_blocks.front().box;
  r.column = block.max[1] - block.min[1];
  for (double depth = 2 * support; depth <= r.column - 2 * support + 1e-9; depth += support) {
    const double y = r.surface - depth;
    double sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.type[i] != ParticleType::Liquid) continue;
      const Vec3& x = p.position[i];
      if (std::abs(double(x.y) - y) > 0.5 * h || side_walls_within(x, 2 * support) > 0) continue;
      sum += pressure_sum[p.id[i]] / samples;
      ++count;
    }
    r.pressure_by_depth.emplace_back(depth, count > 0 ? sum / count : std::nan(""));
  }
  r.outside = liquid_outside(p, tank, 0.5 * h);
  return r;
}

}  // namespace upf::testing
