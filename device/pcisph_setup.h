// What the device pipeline's PCISPH needs of the world and the solver, as plain values: made on
// the host (device_pipelines.cpp) from World and PcisphSolver, so the pipeline's source, which
// nvcc builds too, needs none of their headers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "framework/core/vec3.h"

namespace upf::device {

struct PcisphSetup {
  // PcisphSolver's parameters (pcisph_solver.h).
  double eta = 0, stop_percentile = 0;
  int min_iterations = 0, max_iterations = 0;
  double delta_scale = 0;  // delta = delta_scale / dt^2
  // Per material: FluidMaterialTable's constants and whether the solver moves it.
  std::vector<Real> rest_density, viscosity, boundary_viscosity;
  std::vector<std::uint8_t> owns;
  // The world's settings.
  Vec3 gravity{};
  Real support_radius = 0;
  int reorder_every = 0;
  int threads = 0;
  std::vector<std::string> stages;  // the solver's stage names, for the metrics
  // Field names.
  std::string density, pressure, predicted_density, predicted_position;
};

}  // namespace upf::device
