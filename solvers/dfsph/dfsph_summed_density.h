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
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/summed_density.h"

namespace upf {

// rho_base_i += half the excess of rho*_i over the linear prediction rho_base_i + dt Drho/Dt(v*):
// the linear prediction at the current v* moves halfway to rho*. Only an excess moves it (a linear
// prediction above rho* errs on the safe side). Half, not all: the prediction's slope is taken at
// the step's start, shallower than the summed density's at x* where particles close in on a wall,
// so the whole excess over-corrects; on DamBreakModel at eta 2 % a full re-base drove a particle
// to 104 m/s at the water's first impact on the floor (step 48), and half holds it.
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
    if (rho_star[i] > linear) rho_base[i] += kSummedDensityRelaxation * (rho_star[i] - linear);
  }
};

}  // namespace upf
