// The scenes of the coupling tests, shared by the tests of one solver and those of every fluid
// solver (test_every_fluid_solver.cpp), and what they measure: bodies' states and momenta.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "coupling/bodies/rigid_body_system.h"
#include "framework/world/world.h"

namespace upf::testing {

inline const std::string kTestMeshes = std::string(UPF_SOURCE_DIR) + "/assets/meshes/";

// A 0.5 m cube tank at 2 cm spacing, water 0.3 m deep, one rigid body of `density` made from
// `mesh` (an asset) scaled by `scale` with its centre at `position`. `solver`: a name or an
// object {"name": ..., parameters}.
inline nlohmann::json tank_with_body(const nlohmann::json& solver, double density,
                                     const std::string& mesh, double scale,
                                     const std::vector<double>& position) {
  return {
      {"particle_spacing", 0.02},
      {"materials",
       {{"water", {{"type", "liquid"}, {"viscosity", 0.002}, {"solver", solver}}},
        {"walls", {{"type", "frozen"}}},
        {"solid", {{"type", "rigid"}, {"density", density}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.5, 0.5, 0.5}}}}},
      {"fluid_blocks", {{{"material", "water"}, {"min", {0, 0, 0}}, {"max", {0.5, 0.3, 0.5}}}}},
      {"bodies",
       {{{"name", "body"},
         {"material", "solid"},
         {"mesh", {{"file", kTestMeshes + mesh}, {"scale", scale}, {"position", position}}}}}},
      {"time", {{"dt_max", 0.002}}},
  };
}

// Without gravity or viscosity, a 12 cm cube of density 500 shot at 0.5 m/s into a floating
// block of water in a closed 1.4 m tank; steps of 0.4 ms. The splash reaches the walls at about
// 0.45 s.
inline nlohmann::json cube_shot_into_water(const nlohmann::json& solver) {
  return {
      {"gravity", {0, 0, 0}},
      {"particle_spacing", 0.02},
      {"materials",
       {{"water", {{"type", "liquid"}, {"viscosity", 0.0}, {"solver", solver}}},
        {"walls", {{"type", "frozen"}}},
        {"solid", {{"type", "rigid"}, {"density", 500}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {1.4, 0.6, 0.6}}}}},
      {"fluid_blocks",
       {{{"material", "water"}, {"min", {0.4, 0.16, 0.16}}, {"max", {0.7, 0.44, 0.44}}}}},
      {"bodies",
       {{{"name", "cube"},
         {"material", "solid"},
         {"mesh",
          {{"file", kTestMeshes + "unit_box.obj"},
           {"scale", 0.12},
           {"position", {0.28, 0.3, 0.3}}}},
         {"velocity", {0.5, 0, 0}}}}},
      {"time", {{"fixed_dt", 0.0004}}},
  };
}

// One grain of `grain_density` and `radius` at (0.15, 0.3, 0.15) in a 0.3 x 0.5 x 0.3 m tank at
// 2 cm spacing, with `velocity`, under `g`. Water fills the tank 0.46 m deep, or, `floating`, is a
// block away from every wall (walls push back: an external force) without viscosity (the shared
// Laplacian viscosity is not momentum-symmetric where densities differ).
inline nlohmann::json grain_in_water(const nlohmann::json& solver, double grain_density,
                                     double radius, const std::vector<double>& g,
                                     const std::vector<double>& velocity, bool floating) {
  const std::vector<double> water_min =
      floating ? std::vector<double>{0.05, 0.2, 0.05} : std::vector<double>{0, 0, 0};
  const std::vector<double> water_max =
      floating ? std::vector<double>{0.25, 0.4, 0.25} : std::vector<double>{0.3, 0.46, 0.3};
  const double y = 0.3;
  return {{"gravity", g},
          {"particle_spacing", 0.02},
          {"materials",
           {{"water",
             {{"type", "liquid"},
              {"viscosity", floating ? 0.0 : 0.002},
              {"drag_viscosity", 1e-3},
              {"solver", solver}}},
            {"walls", {{"type", "frozen"}}},
            {"bead",
             {{"type", "granular"},
              {"density", grain_density},
              {"radius", radius},
              {"normal_stiffness", 1e4}}}}},
          {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.3, 0.5, 0.3}}}}},
          {"fluid_blocks", {{{"material", "water"}, {"min", water_min}, {"max", water_max}}}},
          {"granular_blocks",
           {{{"material", "bead"},
             {"min", {0.15 - radius, y - radius, 0.15 - radius}},
             {"max", {0.15 + radius, y + radius, 0.15 + radius}},
             {"velocity", velocity}}}},
          {"time", {{"dt_max", 0.002}}}};
}

// Two bodies of a frozen material added to the dam break (samples/dam_break.json), each reporting
// the fluid's force on it (solvers/fluid/boundary_reactions.h): a block on the floor in the
// surge's path and a paddle turning at 3 rad/s further on. The water's solver gets the wall
// pressure, which frozen body particles carry and take back.
inline void add_fixed_block_and_paddle(nlohmann::json& doc) {
  doc["materials"]["steel"] = {{"type", "frozen"}};
  doc["materials"]["water"]["solver"]["wall_pressure"] = 1;
  auto box = [](const char* name, std::vector<double> scale, std::vector<double> position) {
    return nlohmann::json{
        {"name", name},
        {"material", "steel"},
        {"mesh",
         {{"file", kTestMeshes + "unit_box.obj"}, {"scale", scale}, {"position", position}}}};
  };
  doc["bodies"] = {box("block", {0.12, 0.16, 0.16}, {0.8, 0.08, 0.2}),
                   box("paddle", {0.24, 0.06, 0.24}, {1.05, 0.18, 0.2})};
  doc["bodies"][1]["motion"] = {{"angular_velocity", {0, 0, 3.0}}};
}

inline const RigidBodySystem& bodies_of(const World& world) {
  return dynamic_cast<const RigidBodySystem&>(*world.body_systems().front());
}

// Sum of m v over the particles of `type`, kg m/s.
inline Eigen::Vector3d momentum_of(const Particles& p, ParticleType type) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == type)
      sum += double(p.mass[i]) * Eigen::Vector3d(double(p.velocity[i].x), double(p.velocity[i].y),
                                                 double(p.velocity[i].z));
  return sum;
}

}  // namespace upf::testing
