// The hydrostatic tank of samples/hydrostatic_tank.json (a 0.3 x 0.5 x 0.3 m water block at rest
// in a 0.3 x 0.7 x 0.3 m tank), run with any fluid solver and measured the same way: settle, then
// average each particle's pressure over a window, then read it in horizontal slabs at several
// depths away from the walls and compare with Pascal's law p = rho0 g d.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "scene_helpers.h"

namespace upf::testing {

struct DepthPressure {
  double depth = 0;     // m below the free surface: the slab's centre
  double measured = 0;  // Pa, time-averaged, slab-averaged
  double expected = 0;  // Pa, rho0 g d
  // Pa, rho0 g (surface - y) averaged over the slab's particles. The slab holds about one layer,
  // which may sit up to half a spacing from the centre: 12 % of the shallowest depth at 2.5 cm.
  double expected_at_particles = 0;
  int particles = 0;  // in the slab
  double relative_error() const { return (measured - expected) / expected; }
  double relative_error_at_particles() const {
    return (measured - expected_at_particles) / expected_at_particles;
  }
};

// One lattice layer of liquid, counted up from the floor (layer 0 touches it), over the tank's
// interior columns (two support radii from the side walls): what a floor or wall pressure sensor
// reads is the first layer's pressure.
struct LayerPressure {
  int layer = 0;
  double height = 0;         // m, the mean height of its particles
  double measured = 0;       // Pa, time-averaged, layer-averaged
  double expected = 0;       // Pa, rho0 g (surface - height)
  double density_error = 0;  // time-averaged (rho - rho0) / rho0, the layer's largest
  int particles = 0;
  double relative_error() const { return (measured - expected) / expected; }
};

struct HydrostaticTankResult {
  SolverStats last_step;  // the solver's statistics at the end of the window
  std::uint64_t steps = 0;
  double max_error = 0;        // largest compression of the `density` field, tank edges apart
  double max_error_edges = 0;  // the same within one support radius of two or more walls
  double surface = 0;          // m: see SurfaceReference
  double v_rms = 0;            // m/s over the liquid
  std::vector<DepthPressure> slabs;
  std::vector<LayerPressure> layers;  // from the floor up, to the surface
  // The largest time-averaged density error of any liquid particle, walls and edges included.
  double max_mean_density_error = 0;
  bool all_inside = true;  // no liquid particle past the first wall layer
};

// The block's height and the tank's width in the sample.
inline constexpr double kTankColumn = 0.5, kTankWidth = 0.3, kTankHeight = 0.7;

// Where depth is measured from.
//   TopParticle: the highest liquid particle + half a spacing.
//   TopLayer:    the mean height of the top layer's particles (as many as one lattice layer of the
//                block holds) + half a spacing. Weakly compressible fluids keep ringing at their
//                acoustic mode, and the highest particle of their jiggling top layer stood 4 mm
//                above the layer's mean (WCSPH, 2.5 cm spacing): a 4 % error at the shallowest
//                slab.
enum class SurfaceReference { TopParticle, TopLayer };

// Runs `doc` (the sample, possibly with another solver or spacing) for settle_time, then averages
// the pressure over average_time, sampled every 0.01 s.
inline HydrostaticTankResult run_hydrostatic_tank(
    const nlohmann::json& doc, int threads, double settle_time, double average_time,
    SurfaceReference reference = SurfaceReference::TopParticle) {
  TestWorld tw(doc, threads);
  tw.run_until(settle_time);
  const World& w = *tw.world;
  const Particles& p = w.particles();
  std::map<ParticleId, double> pressure_sum, density_sum;
  int samples = 0;
  while (w.time() < settle_time + average_time - 1e-12) {
    tw.run_until(std::min(w.time() + 0.01, settle_time + average_time));
    const auto& pr = *p.find_scalar("pressure");
    const auto& rho = *p.find_scalar("density");
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.type[i] != ParticleType::Liquid) continue;
      pressure_sum[p.id[i]] += double(pr[i]);
      density_sum[p.id[i]] += double(rho[i]);
    }
    ++samples;
  }
  HydrostaticTankResult r;
  const double rho0 = 1000, g = 9.81;
  const double h = tw.scene.world.spacing;
  const double support = tw.scene.world.support_radius();
  r.last_step = w.last_step().solver;
  r.steps = w.step_count();

  const auto& density = *p.find_scalar("density");
  auto walls_within_support = [&](const Vec3& x) {
    int walls = 0;
    walls += x.x < support || x.x > kTankWidth - support;
    walls += x.y < support;
    walls += x.z < support || x.z > kTankWidth - support;
    return walls;
  };
  double top = 0, v2 = 0;
  std::size_t fluid = 0;
  std::vector<double> heights;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const Vec3& x = p.position[i];
    const double e = (double(density[i]) - rho0) / rho0;
    double& max_error = walls_within_support(x) >= 2 ? r.max_error_edges : r.max_error;
    max_error = std::max(max_error, e);
    top = std::max(top, double(x.y));
    heights.push_back(double(x.y));
    v2 += double(squared_norm(p.velocity[i]));
    ++fluid;
    r.all_inside = r.all_inside && x.x > -0.5 * h && x.x < kTankWidth + 0.5 * h && x.y > -0.5 * h &&
                   x.y < kTankHeight + 0.5 * h && x.z > -0.5 * h && x.z < kTankWidth + 0.5 * h;
  }
  r.surface = top + 0.5 * h;
  if (reference == SurfaceReference::TopLayer) {
    const auto layer = std::min(heights.size(), std::size_t(std::lround(kTankWidth / h)) *
                                                    std::size_t(std::lround(kTankWidth / h)));
    std::partial_sort(heights.begin(), heights.begin() + std::ptrdiff_t(layer), heights.end(),
                      std::greater<double>());
    double sum = 0;
    for (std::size_t k = 0; k < layer; ++k) sum += heights[k];
    r.surface = sum / double(layer) + 0.5 * h;
  }
  r.v_rms = std::sqrt(v2 / double(fluid));

  // Slabs one spacing thick at depths >= 2 support radii, away from the side walls.
  for (double depth = 2 * support; depth <= kTankColumn - 2 * support + 1e-9; depth += support) {
    const double y = r.surface - depth;
    DepthPressure slab;
    slab.depth = depth;
    slab.expected = rho0 * g * depth;
    double sum = 0, depth_sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.type[i] != ParticleType::Liquid) continue;
      const Vec3& x = p.position[i];
      if (std::abs(double(x.y) - y) > 0.5 * h) continue;
      if (!in_interior_columns(x, kTankWidth, 2 * support)) continue;
      sum += pressure_sum[p.id[i]] / samples;
      depth_sum += r.surface - double(x.y);
      ++slab.particles;
    }
    slab.measured = slab.particles > 0 ? sum / slab.particles : 0;
    slab.expected_at_particles = slab.particles > 0 ? rho0 * g * depth_sum / slab.particles : 0;
    r.slabs.push_back(slab);
  }

  // Lattice layers from the floor: the liquid ranked by height, as many to a layer as one lattice
  // layer of the block holds (the first layer may sit well below its lattice height); pressures
  // from the interior columns only.
  std::vector<std::pair<double, std::size_t>> by_height;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    by_height.emplace_back(double(p.position[i].y), i);
    const double e = (density_sum[p.id[i]] / samples - rho0) / rho0;
    r.max_mean_density_error = std::max(r.max_mean_density_error, e);
  }
  std::sort(by_height.begin(), by_height.end());
  const auto per_layer = std::size_t(std::lround(kTankWidth / h) * std::lround(kTankWidth / h));
  r.layers.resize(by_height.size() / per_layer);
  for (std::size_t rank = 0; rank < r.layers.size() * per_layer; ++rank) {
    const std::size_t i = by_height[rank].second;
    LayerPressure& layer = r.layers[rank / per_layer];
    layer.layer = int(rank / per_layer);
    const Vec3& x = p.position[i];
    if (!in_interior_columns(x, kTankWidth, 2 * support)) continue;
    layer.measured += pressure_sum[p.id[i]] / samples;
    layer.height += double(x.y);
    layer.density_error =
        std::max(layer.density_error, (density_sum[p.id[i]] / samples - rho0) / rho0);
    ++layer.particles;
  }
  for (auto& layer : r.layers) {
    if (layer.particles == 0) continue;
    layer.measured /= layer.particles;
    layer.height /= layer.particles;
    layer.expected = rho0 * g * (r.surface - layer.height);
  }
  return r;
}

inline void print_hydrostatic_tank(const HydrostaticTankResult& r) {
  std::printf("%llu steps, avg density error %.5f, max %.5f (at tank edges %.5f), iterations %d\n",
              static_cast<unsigned long long>(r.steps), r.last_step.avg_density_error, r.max_error,
              r.max_error_edges, r.last_step.iterations);
  std::printf("surface %.4f m, v_rms %.5f m/s\n", r.surface, r.v_rms);
  for (const auto& s : r.slabs)
    std::printf(
        "depth %.3f m: p = %.1f Pa, rho0 g d = %.1f Pa (%+.2f %%), at the particles' depths %.1f "
        "Pa (%+.2f %%)\n",
        s.depth, s.measured, s.expected, 100 * s.relative_error(), s.expected_at_particles,
        100 * s.relative_error_at_particles());
  std::printf("largest time-averaged density error %.5f\n", r.max_mean_density_error);
  for (const auto& l : r.layers)
    std::printf(
        "layer %2d at %.4f m (%3d particles): p = %7.1f Pa, rho0 g d = %7.1f Pa (%+.2f %%), "
        "density error up to %+.3f %%\n",
        l.layer, l.height, l.particles, l.measured, l.expected, 100 * l.relative_error(),
        100 * l.density_error);
}

// The sample with its water moved by `solver` (a solver object: {"name": ..., params...}).
inline nlohmann::json hydrostatic_tank_with(const nlohmann::json& solver, double spacing) {
  auto doc = load_sample_json("hydrostatic_tank.json");
  doc["materials"]["water"]["solver"] = solver;
  doc["particle_spacing"] = spacing;
  return doc;
}

}  // namespace upf::testing
