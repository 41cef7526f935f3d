// The density summed where a step will leave the particles, x* = x + dt v (as PCISPH predicts,
// Solenthaler & Pajarola 2009): the honest check of a solve that bounds a density predicted
// linearly from velocities (DFSPH's and IISPH's summed_density_check, dfsph_summed_density.h and
// iisph_solve.h). C++17: nvcc builds it too.
#pragma once

#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_view.h"

namespace upf {

// The share of the excess of the summed density over the linear prediction that a re-base takes
// (dfsph_summed_density.h, iisph_kernels.h explain why not all of it).
inline constexpr Real kSummedDensityRelaxation = Real(0.5);

// x* = x + dt v: with the particles' velocities (walls, bodies, other solvers' liquids), then,
// over the solver's own particles, with the velocities the step will end with.
struct PredictPositionStage {
  const Vec3* x;
  const Vec3* v;
  Real dt;
  Vec3* x_star;
  UPF_HD void operator()(std::uint32_t i) const { x_star[i] = x[i] + v[i] * dt; }
};

// rho*_i, summed at the predicted positions as PCISPH sums it (fluid_density).
struct SummedPredictedDensityStage {
  FluidView f;
  const Vec3* x_star;
  Real* rho_star;
  UPF_HD void operator()(std::uint32_t i) const {
    Real ratio = 1;
    rho_star[i] = fluid_density(f, x_star, i, f.density_contrast ? &ratio : nullptr);
  }
};

}  // namespace upf
