// The per-particle functions and stages of Implicit Incompressible SPH (Ihmsen, Cornelis,
// Solenthaler, Horvath & Teschner 2014, "Implicit incompressible SPH", IEEE TVCG 20(3)), in the
// form with pressure accelerations (Koschier, Bender, Solenthaler & Teschner 2019, "Smoothed
// particle hydrodynamics techniques for the physics based simulation of fluids and solids",
// Eurographics tutorial, section 3.4): the same relaxed Jacobi iteration on the pressure Poisson
// equation, with the off-diagonal sum evaluated through the pressure accelerations.
//
//   a_i   = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad W_ij
//           - rho0_i (p_i + p_b)/rho_i^2 sum_b V_b grad W_ib
//   (A p)_i = dt^2 [ sum_j m_j (a_i - a_j) . grad W_ij + rho0_i a_i . sum_b V_b grad W_ib ]
//   a_ii  = -dt^2 D_i / rho_i^2                     (D_i: solvers/fluid/density_rate.h)
//   p_i  <- max(0, p_i + omega (rho0 - rho_adv_i - (A p)_i) / a_ii)
// with rho_adv_i = rho_i + dt Drho_i/Dt at v_adv = v + dt a_other. Akinci et al. 2012
// boundaries, Psi_b = rho0_i V_b, with the wall pressure p_b of boundary_pressure.h; the diagonal
// takes i's pressure through p_i only (in p_b it is one kernel weight among many). Where liquids
// differ in rest density, the sums take the number-density forms of density_contrast.h.
#pragma once

#include "solvers/fluid/boundary_pressure.h"
#include "solvers/fluid/density_contrast.h"
#include "solvers/fluid/density_rate.h"
#include "solvers/fluid/summed_density.h"

namespace upf {

// rho_adv_i = rho_i + dt Drho_i/Dt at the advected velocities.
struct IisphAdvectedDensityStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Real* boundary_divergence;
  const Real* density;
  const Vec3* v_adv;
  Real dt;
  Real* rho_adv;
  UPF_HD void operator()(std::uint32_t i) const {
    rho_adv[i] = density[i] + dt * density_rate(f, fluid_gradient, boundary_gradient[i],
                                                boundary_divergence[i], v_adv, i);
  }
};

// The warm start: half of the previous step's pressure (the paper's initial guess).
struct HalvePressureStage {
  Real* pressure;
  UPF_HD void operator()(std::uint32_t i) const { pressure[i] *= Real(0.5); }
};

// The pressure acceleration a_i at pressures `pressure` (0 for particles not owned).
struct IisphPressureAccelerationStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Real* density;
  const Real* pressure;
  Vec3* a_pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real pi = pressure[i] / (density[i] * density[i]);
    const Real pb =
        mirrored_pressure_factor(f, PressureOverDensitySquared{pressure, density, 1}, i);
    Vec3 a = boundary_pressure_acceleration(f, boundary_gradient[i], pi, pb, i);
    for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
      const std::uint32_t j = f.fluid.indices[k];
      a -= fluid_gradient.at(f, i, k) *
           pressure_pair(f, i, j, pi, pressure[j] / (density[j] * density[j]));
    }
    a_pressure[i] = a;
  }
};

// One relaxed Jacobi update: the density predicted with the current pressures, rho_adv + (A p),
// goes to `predicted` (the stopping test), the new pressure to `next`.
struct IisphPressureUpdateStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Real* density;
  const Real* inverse_diagonal;  // 1 / D_i
  const Real* rho_adv;
  const Vec3* a_pressure;
  const Real* pressure;
  Real dt;
  Real omega;
  Real* predicted;
  Real* next;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real rho0 = f.rest_density[f.material[i]];
    const Vec3 ai = a_pressure[i];
    Real change = rho0 * dot(ai, boundary_gradient[i]);
    for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
      const std::uint32_t j = f.fluid.indices[k];
      change += density_weight(f, i, j) * dot(ai - a_pressure[j], fluid_gradient.at(f, i, k));
    }
    change *= dt * dt;
    predicted[i] = rho_adv[i] + change;
    // a_ii = -dt^2 D_i / rho_i^2; no neighbours (D_i = 0): no pressure.
    if (inverse_diagonal[i] == Real(0)) {
      next[i] = 0;
      return;
    }
    const Real a_ii = -dt * dt / (density[i] * density[i] * inverse_diagonal[i]);
    const Real p = pressure[i] + omega * (rho0 - predicted[i]) / a_ii;
    next[i] = p > Real(0) ? p : Real(0);
  }
};

// x*_i = x_i + dt (v_adv_i + dt a_i): where the step leaves i with the pressure accelerations a.
struct IisphPredictPositionStage {
  const Vec3* x;
  const Vec3* v_adv;
  const Vec3* a_pressure;
  Real dt;
  Vec3* x_star;
  UPF_HD void operator()(std::uint32_t i) const {
    x_star[i] = x[i] + (v_adv[i] + a_pressure[i] * dt) * dt;
  }
};

// rho_adv_i += half the excess of the summed rho*_i over the linear prediction rho_adv_i + (A p)_i
// at the final pressures (`predicted`): the solve's prediction at those pressures moves halfway
// to rho*. Only an excess moves it (a linear prediction above rho* errs on the safe side); half,
// as DFSPH's re-base (dfsph_summed_density.h), because the whole excess over-corrects where
// particles close in on a wall.
struct IisphRebaseStage {
  const Real* rho_star;
  const Real* predicted;
  Real* rho_adv;
  UPF_HD void operator()(std::uint32_t i) const {
    if (rho_star[i] > predicted[i])
      rho_adv[i] += kSummedDensityRelaxation * (rho_star[i] - predicted[i]);
  }
};

}  // namespace upf
