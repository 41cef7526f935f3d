// DFSPH's optional check of the constant-density solve against the densities summed where the step
// will leave the particles (DfsphSettings::summed_density_check), so that "the largest
// compression below eta" holds at the particles, as PCISPH's stopping test holds it.
//
// Bender & Koschier's solve (2015, 2017) bounds a density predicted linearly from the velocity
// divergence, rho_adv = rho + dt Drho/Dt(v*); at the particles the next step sums a density at
// x + dt v* that the linear prediction underestimates where particles converge fast (the dam
// break's largest error reached 10-13 % at eta 1 %). The check sums rho* at x + dt v* (as PCISPH
// predicts, Solenthaler & Pajarola 2009) with the step's neighbour lists; where its stopping error
// exceeds eta it re-bases the linear prediction on it, so that the solve's own estimate equals
// rho* at the current v*, and iterates on, for a few rounds (kDfsphSummedDensityRounds). C++17:
// nvcc builds it too.
#pragma once

#include "solvers/fluid/density_rate.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_view.h"

namespace upf {

// x* = x + dt v: with the particles' velocities (walls, bodies, other solvers' liquids), then,
// over the solver's own particles, with v*.
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

// rho_base_i += the excess of rho*_i over the linear prediction rho_base_i + dt Drho/Dt(v*): the
// linear prediction from here on equals rho* at the current v*. Only an excess moves it (a linear
// prediction above rho* errs on the safe side).
struct RebaseDensityStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Real* boundary_divergence;
  const Vec3* v_star;
  Real dt;
  const Real* rho_star;
  Real* rho_base;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real linear = rho_base[i] + dt * density_rate(f, fluid_gradient, boundary_gradient[i],
                                                        boundary_divergence[i], v_star, i);
    if (rho_star[i] > linear) rho_base[i] += rho_star[i] - linear;
  }
};

}  // namespace upf
