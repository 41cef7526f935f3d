// Everything a device pipeline is made from, as plain values (device_pipelines.cpp makes it from
// a prepared World): the world's settings and, in the world's stepping order, one setup per
// solver. The pipeline's source, which nvcc builds too, needs no world header.
#pragma once

#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "device/fluid_setup.h"
#include "framework/core/vec3.h"
#include "framework/world/periodic_box.h"
#include "solvers/dem/dem_spring_state.h"
#include "solvers/dem/dem_step_setup.h"

namespace upf::device {

// WorldSettings and the coupling arrays (coupling.h) the pipeline keeps.
struct WorldSetup {
  Vec3 gravity{};
  Real support_radius = 0;
  int reorder_every = 0;
  int threads = 0;
  bool boundary_force = false;  // CouplingArray::BoundaryForce is active
  bool liquid_force = false;    // CouplingArray::LiquidForce is active
  PeriodicBox periodic;         // WorldSettings::periodic: images as ghosts (device_images.h)
};

// A fluid solver: the shared constants and its pressure method's.
using FluidMethodSetup = std::variant<PcisphSetup, IisphSetup, DfsphSetup, WcsphSetup, SphSetup>;
struct FluidSolverSetup {
  FluidSetup fluid;
  FluidMethodSetup method;
};

// A DEM solver: its constants, and the host solver's springs to start from and give back.
struct DemSolverSetup {
  DemStepSetup step;
  std::vector<std::string> stages;
  std::function<DemSpringState()> load_springs;
  std::function<void(const DemSpringState&)> store_springs;
};

using SolverSetup = std::variant<FluidSolverSetup, DemSolverSetup>;

struct PipelineSetup {
  WorldSetup world;
  std::vector<SolverSetup> solvers;  // in the world's stepping order
};

}  // namespace upf::device
