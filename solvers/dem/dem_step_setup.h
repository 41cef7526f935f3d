// A DEM solver's constants for one scene as plain values (DemSolver::step_setup): what a device
// pipeline needs to run the solver's step (dem_steps.h) on its own arrays. C++17: nvcc builds it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "framework/core/vec3.h"
#include "framework/world/container_box.h"
#include "solvers/dem/dem_contact.h"

namespace upf {

struct DemStepSetup {
  DemModel model = DemModel::Linear;
  // DemPairs' tables: grain pairs (materials x materials), walls and boundary particles.
  std::vector<DemPairParams> pairs, walls, boundary;
  std::size_t materials = 0;
  Real boundary_radius = 0;
  std::vector<std::uint8_t> owns;  // per material: the solver's grains
  std::vector<ContainerBox> boxes;
  Vec3 gravity{};
  Real substep = 0;           // s, the longest sub-step
  Real skin = 0;              // m, beyond the longest contact
  Real list_radius = 0;       // m, of the contact candidates' lists
  bool reactions = false;     // forces on rigid boundary particles wanted (boundary_force)
  bool liquid = false;        // the scene has liquid: drag, buoyancy, voidage
  bool liquid_force = false;  // the liquid takes the reactions (liquid_force)
  std::vector<Real> liquid_density, liquid_viscosity;   // by material
  std::string radius, angular_velocity, force, torque;  // the solver's fields
  std::string wall_normal, wall_shear, contact_load;    // recorded for export
};

}  // namespace upf
