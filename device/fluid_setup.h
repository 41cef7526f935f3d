// What the device pipeline needs of the world and of a fluid solver, as plain values: made on the
// host (device_pipelines.cpp) from World and the solver, so the pipeline's source, which nvcc
// builds too, needs none of their headers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "framework/core/vec3.h"
#include "solvers/dfsph/dfsph_steps.h"
#include "solvers/fluid/implicit_viscosity.h"
#include "solvers/fluid/surface_force_view.h"
#include "solvers/iisph/iisph_solve.h"
#include "solvers/pcisph/pcisph_correction_loop.h"
#include "solvers/sph/sph_steps.h"

namespace upf::device {

// FluidSolverState's constants.
struct FluidSetup {
  // Per material: FluidMaterialTable's constants and whether the solver moves it.
  std::vector<Real> rest_density, viscosity, boundary_viscosity;
  Real viscosity_factor = 10;  // the Laplacian's F (viscosity_operator.h)
  std::vector<std::uint8_t> owns;
  // FluidMaterialTable's surface tension: the model, per material its coefficient, per pair
  // Akinci's beta (SurfaceForceView).
  SurfaceTensionModel surface_model = SurfaceTensionModel::None;
  std::vector<Real> cohesion, adhesion;
  bool has_adhesion = false;
  // FluidMaterialTable's implicit viscosity: on or off, its tolerance and cap (its fields are
  // found by name, implicit_viscosity.h).
  bool implicit_viscosity = false;
  ImplicitViscositySettings viscosity_solve{};
  bool wall_friction = false;  // FluidSolverState::wall_list: walls' velocities extrapolated
  // FluidSolverState::reaction_query: the body particles whose reactions a body system sums; 0:
  // none.
  TypeMask reaction_query = 0;
  // Keep grad W_ij per fluid pair (12 B a pair, as the CPU path does) instead of recomputing it
  // where used: the same bits either way (FluidGradients).
  bool store_gradients = false;
  bool wall_pressure = false;       // FluidSolverState::wall_pressure
  bool density_contrast = false;    // FluidMaterialTable::density_contrast
  std::vector<std::string> stages;  // the solver's stage names, for the metrics
  std::string density = "density", pressure = "pressure";  // the exported fields
};

// PcisphSolver's correction loop and stopping test.
struct PcisphSetup {
  PcisphLoopSettings loop{};
  double stop_percentile = 0;
  std::string predicted_density, predicted_position, scaled_pressure;  // its fields
};

// WcsphSolver's constants (Becker & Teschner 2007).
struct WcsphSetup {
  std::vector<Real> tait_factor;  // per material: B = rho0 c^2 / 7
  Real artificial_viscosity = 0;  // 2 alpha h c; 0: none
};

// IisphSolver's solve and stopping test (Ihmsen et al. 2014).
struct IisphSetup {
  IisphSettings solve{};
  double stop_percentile = 0;
};

// DfsphSolver's solves and stopping test (Bender & Koschier 2015, 2017).
struct DfsphSetup {
  DfsphSettings solve{};
  double stop_percentile = 0;
  std::string density_stiffness, divergence_stiffness;  // its fields (warm starts)
};

// SphSolver's constants (Müller et al. 2003).
struct SphSetup {
  SphKernelChoice kernels{};
  Real stiffness = 0;  // k of p = k (rho - rho0)
  Real mu = 0;         // the paper's dynamic viscosity; 0: none
};

}  // namespace upf::device
