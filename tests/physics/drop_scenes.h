// Scenes of free drops without gravity, for the surface tension tests: a ball (or a cube) of water
// of radius R at `spacing`, in the middle of a closed box far enough from it that no wall is ever
// within reach, with a surface tension sigma.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace upf::testing {

struct DropScene {
  double radius = 0.02;     // m
  double spacing = 0.0025;  // m
  double sigma = 0.0728;    // N/m
  double viscosity = 1e-5;  // m^2/s, the shared Laplacian viscosity
  std::string solver = "pcisph";
  std::string model;  // the surface tension model; empty: the default
  bool cube = false;  // a cube of side 2R instead of the ball
};

inline nlohmann::json drop_scene(const DropScene& d) {
  // The box: the drop's lattice plus room for a ball as wide as the cube's diagonal.
  const double half = 2.0 * d.radius + 4 * d.spacing;
  nlohmann::json water = {{"type", "liquid"},
                          {"density", 1000},
                          {"viscosity", d.viscosity},
                          {"surface_tension", d.sigma},
                          {"solver", {{"name", d.solver}}}};
  if (!d.model.empty()) water["surface_tension_model"] = d.model;
  nlohmann::json block = {{"material", "water"},
                          {"min", {half - d.radius, half - d.radius, half - d.radius}},
                          {"max", {half + d.radius, half + d.radius, half + d.radius}}};
  if (!d.cube) block["shape"] = "ball";
  return {{"name", "drop"},
          {"gravity", {0, 0, 0}},
          {"particle_spacing", d.spacing},
          {"materials", {{"water", water}, {"walls", {{"type", "frozen"}}}}},
          {"containers",
           {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {2 * half, 2 * half, 2 * half}}}}},
          {"fluid_blocks", {block}},
          {"time", {{"dt_max", 0.002}}}};
}

}  // namespace upf::testing
