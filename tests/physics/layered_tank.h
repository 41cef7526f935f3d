// Two liquids layered at rest in a closed tank, the lighter on top: the scene and what the
// layered-liquid tests measure. Depths are read from the liquids' own surfaces, as in
// hydrostatic_tank.h: the free surface at the highest light particle + half a spacing, the
// interface halfway between the heavy liquid's top layer and the light liquid's bottom layer.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "scene_helpers.h"

namespace upf::testing {

inline constexpr double kLayerTankWidth = 0.3, kLayerTankHeight = 0.7, kLayerDepth = 0.2;

// A heavy layer (0 to 0.2 m) under a light one (0.2 to 0.4 m) in a 0.3 x 0.7 x 0.3 m tank, 2 cm
// spacing (4,500 liquid particles).
inline nlohmann::json layered_tank(const std::string& solver, double heavy, double light,
                                   double spacing = 0.02) {
  // The wall pressure of boundary_pressure.h: without it the liquid sinks along the side walls and
  // rises in the middle, and that convection carried water 5.8 cm up the walls into the oil in 5 s.
  return {
      {"name", "layered_tank"},
      {"gravity", {0, -9.81, 0}},
      {"particle_spacing", spacing},
      {"materials", two_liquid_materials(solver, "heavy", heavy, "light", light, true)},
      {"containers",
       {{{"material", "walls"},
         {"min", {0, 0, 0}},
         {"max", {kLayerTankWidth, kLayerTankHeight, kLayerTankWidth}}}}},
      {"fluid_blocks",
       {{{"material", "heavy"},
         {"min", {0, 0, 0}},
         {"max", {kLayerTankWidth, kLayerDepth, kLayerTankWidth}}},
        {{"material", "light"},
         {"min", {0, kLayerDepth, 0}},
         {"max", {kLayerTankWidth, 2 * kLayerDepth, kLayerTankWidth}}}}},
      {"time", {{"end", 5.0}, {"dt_max", 0.002}}},
  };
}

struct LayerSlab {
  double height = 0;    // m, the slab's centre
  double measured = 0;  // Pa, time- and slab-averaged, interior columns
  double expected = 0;  // Pa, the layered hydrostatic pressure at the slab's particles
  int particles = 0;
  double relative_error() const { return (measured - expected) / expected; }
};

struct LayeredTankResult {
  double surface = 0, interface = 0;  // m
  double gap =
      0;  // m, the light liquid's bottom layer above the heavy one's top layer (mean heights)
  // How far the deepest particle of each liquid is past the interface into the other (m; a
  // lattice at rest: minus half a spacing).
  double heavy_inside_light = 0, light_inside_heavy = 0;
  std::vector<LayerSlab> slabs;  // from the floor up
  double v_rms = 0;
};

// Runs `doc` to `settle` s, then averages each particle's pressure over `average` s (sampled every
// 0.01 s) and reads it in slabs one spacing thick, two support radii from the side walls and the
// floor, and 2.5 support radii below the free surface (nearer, the kernel sum is deficient and
// one liquid alone reads up to 6 % high: test_hydrostatic_tank.cpp). Material 0 of the scene's
// liquids is the heavy one.
inline LayeredTankResult run_layered_tank(const nlohmann::json& doc, int threads, double settle,
                                          double average) {
  TestWorld tw(doc, threads);
  tw.run_until(settle);
  const World& w = *tw.world;
  const Particles& p = w.particles();
  const MaterialId heavy = *w.materials().find("heavy");
  const double rho_heavy = w.materials()[heavy].param("density");
  const double rho_light = w.materials()[*w.materials().find("light")].param("density");
  std::map<ParticleId, double> pressure_sum;
  int samples = 0;
  while (w.time() < settle + average - 1e-12) {
    tw.run_until(std::min(w.time() + 0.01, settle + average));
    const auto& pressure = *p.find_scalar("pressure");
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Liquid) pressure_sum[p.id[i]] += double(pressure[i]);
    ++samples;
  }
  const double s = tw.scene.world.spacing, support = tw.scene.world.support_radius();
  LayeredTankResult r;
  std::vector<double> heavy_y, light_y;
  double v2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const double y = double(p.position[i].y);
    (p.material[i] == heavy ? heavy_y : light_y).push_back(y);
    v2 += double(squared_norm(p.velocity[i]));
  }
  r.v_rms = std::sqrt(v2 / double(heavy_y.size() + light_y.size()));
  const auto per_layer =
      std::size_t(std::lround(kLayerTankWidth / s) * std::lround(kLayerTankWidth / s));
  std::sort(heavy_y.begin(), heavy_y.end(), std::greater<double>());
  std::sort(light_y.begin(), light_y.end());
  double heavy_top = 0, light_bottom = 0;
  for (std::size_t k = 0; k < per_layer; ++k) {
    heavy_top += heavy_y[k] / double(per_layer);
    light_bottom += light_y[k] / double(per_layer);
  }
  r.surface = light_y.back() + 0.5 * s;
  r.interface = 0.5 * (heavy_top + light_bottom);
  r.gap = light_bottom - heavy_top;
  r.heavy_inside_light = heavy_y.front() - r.interface;
  r.light_inside_heavy = r.interface - light_y.front();

  const double g = 9.81;
  auto hydrostatic = [&](double y) {
    if (y >= r.interface) return rho_light * g * (r.surface - y);
    return rho_light * g * (r.surface - r.interface) + rho_heavy * g * (r.interface - y);
  };
  for (double y = 2 * support; y <= r.surface - 2.5 * support + 1e-9; y += s) {
    LayerSlab slab;
    slab.height = y;
    double sum = 0, expected = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.type[i] != ParticleType::Liquid) continue;
      const Vec3& x = p.position[i];
      if (std::abs(double(x.y) - y) > 0.5 * s) continue;
      if (!in_interior_columns(x, kLayerTankWidth, 2 * support)) continue;
      sum += pressure_sum[p.id[i]] / samples;
      expected += hydrostatic(double(x.y));
      ++slab.particles;
    }
    if (slab.particles == 0) continue;
    slab.measured = sum / slab.particles;
    slab.expected = expected / slab.particles;
    r.slabs.push_back(slab);
  }
  return r;
}

}  // namespace upf::testing

namespace upf::testing {

// A ball of liquid "drop" (radius 0.07 m, centred 0.2 m up) in water at rest, 0.45 m deep in a
// 0.3 x 0.6 x 0.3 m tank: the water block's particles inside the ball take the drop's material
// and mass before the first step.
struct DropInWater {
  TestWorld tw;
  double radius = 0.07;
  Vec3 centre{Real(0.15), Real(0.2), Real(0.15)};
  MaterialId drop = 0;

  static nlohmann::json scene(const std::string& solver, double drop_density) {
    return {
        {"name", "drop_in_water"},
        {"gravity", {0, -9.81, 0}},
        {"particle_spacing", 0.02},
        {"materials", two_liquid_materials(solver, "water", 1000, "drop", drop_density, true)},
        {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.3, 0.6, 0.3}}}}},
        {"fluid_blocks", {{{"material", "water"}, {"min", {0, 0, 0}}, {"max", {0.3, 0.45, 0.3}}}}},
        {"time", {{"end", 1.0}, {"dt_max", 0.002}}},
    };
  }

  DropInWater(const std::string& solver, double drop_density)
      : tw(scene(solver, drop_density), 2, TestWorld::Unprepared{}) {
    World& w = *tw.world;
    drop = *w.materials().find("drop");
    Particles& p = w.particles();
    const double s = tw.scene.world.spacing;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.type[i] != ParticleType::Liquid) continue;
      if (double(norm(p.position[i] - centre)) > radius) continue;
      p.material[i] = drop;
      p.mass[i] = Real(drop_density * s * s * s);
    }
    w.prepare();
  }

  // The drop's centre of mass height.
  double height() const {
    const Particles& p = tw.world->particles();
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.material[i] == drop) {
        sum += double(p.position[i].y);
        ++n;
      }
    return sum / n;
  }
};

}  // namespace upf::testing

namespace upf::testing {

// Rayleigh-Taylor: a heavy layer on a light one, each `depth` deep, in a box `width` wide and a
// few spacings thick (walls all round, a free surface on top), the interface displaced by
// eta0 cos(k x) with
// k = pi / width (the side walls' symmetric mode). Linear theory from rest (Chandrasekhar 1961,
// ch. X; layers of finite depth, the lid's effect e^(-2 k depth) = 0.2 % neglected):
// eta(t) = eta0 cosh(sigma t),
//   sigma^2 = A g k tanh(k depth),  A = (rho_heavy - rho_light) / (rho_heavy + rho_light).
struct RayleighTaylorBox {
  TestWorld tw;
  double width, depth, thickness, spacing;
  MaterialId light = 0;

  static nlohmann::json scene(const std::string& solver, double heavy, double light_density,
                              double width, double depth, double thickness, double spacing) {
    // Inviscid, as the theory, and without the wall pressure: its hydrostatic part supports each
    // particle beside a wall as if it stood in liquid of its own density, and in a slab a few
    // spacings thick every particle stands beside the front and back walls; with it the mode
    // grew at 0.7 sigma.
    return {
        {"name", "rayleigh_taylor"},
        {"gravity", {0, -9.81, 0}},
        {"particle_spacing", spacing},
        {"materials",
         two_liquid_materials(solver, "heavy", heavy, "light", light_density, false, 0)},
        {"containers",
         {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {width, 2.5 * depth, thickness}}}}},
        {"fluid_blocks",
         {{{"material", "heavy"}, {"min", {0, 0, 0}}, {"max", {width, 2 * depth, thickness}}}}},
        {"time", {{"end", 1.0}, {"dt_max", 0.002}}},
    };
  }

  RayleighTaylorBox(const std::string& solver, double heavy, double light_density, double eta0,
                    double width_ = 0.2, double depth_ = 0.2, double thickness_ = 0.03,
                    double spacing_ = 0.005)
      : tw(scene(solver, heavy, light_density, width_, depth_, thickness_, spacing_), 2,
           TestWorld::Unprepared{}),
        width(width_),
        depth(depth_),
        thickness(thickness_),
        spacing(spacing_) {
    World& w = *tw.world;
    light = *w.materials().find("light");
    Particles& p = w.particles();
    const double k = 3.14159265358979 / width;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.type[i] != ParticleType::Liquid) continue;
      const double x = double(p.position[i].x), y = double(p.position[i].y);
      if (y > depth + eta0 * std::cos(k * x)) continue;
      p.material[i] = light;
      p.mass[i] = Real(light_density * spacing * spacing * spacing);
    }
    w.prepare();
  }

  // eta of the cos(k x) mode: the light liquid's height h(x) projected on it,
  //   eta = (2 / width) int h(x) cos(k x) dx = 2 s^3 sum_light cos(k x_i) / (width thickness),
  // each light particle standing for its rest volume s^3.
  double amplitude() const {
    const Particles& p = tw.world->particles();
    const double k = 3.14159265358979 / width;
    double sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.material[i] == light) sum += std::cos(k * double(p.position[i].x));
    return 2 * spacing * spacing * spacing * sum / (width * thickness);
  }
};

}  // namespace upf::testing
