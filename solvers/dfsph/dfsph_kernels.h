// The per-particle functions and stages of Divergence-Free SPH (Bender & Koschier 2015,
// "Divergence-free smoothed particle hydrodynamics", SCA; 2017, "Divergence-free SPH for
// incompressible and viscous fluids", IEEE TVCG 23(3)), written once for host and device.
//
// Both solvers correct a working velocity v with the pressure-like values K_i = kappa_i / rho_i:
//   v_i -= dt [ sum_j m_j (K_i + K_j) grad W_ij + rho0_i (K_i + K_b) sum_b V_b grad W_ib ]
// (the boundary particles of Akinci et al. 2012, Psi_b = rho0_i V_b, with the wall's K_b, the
// Shepard average of the neighbourhood's K: boundary_pressure.h). K_i is chosen so that, with
// the neighbours' K held fixed, particle i's predicted density change cancels its error:
//   K_i = omega (rho_adv_i - rho0_i) / (dt^2 D_i)     (D_i: solvers/fluid/density_rate.h)
// which is the paper's kappa_i = (rho_adv_i - rho0) alpha_i / dt^2 with alpha_i = rho_i / D_i
// divided by rho_i. The constant-density solver predicts rho_adv_i = rho_i + dt Drho_i/Dt at the
// working velocity, clamped below at rho0 (only compression is corrected); the divergence-free
// solver uses rho_adv_i = rho0 + dt max(Drho_i/Dt, 0), so the same K formula cancels the
// density's rate of change, Drho_i/Dt (density_rate.h, with D_i).
// All particles update at once (Jacobi), so the relaxation omega (the paper: 1) damps the
// checkerboard modes that a full step overshoots; dfsph_solver.h says why upf uses 0.5. Where
// liquids differ in rest density, the sums take the number-density forms of density_contrast.h.
#pragma once

#include "solvers/fluid/boundary_pressure.h"
#include "solvers/fluid/density_contrast.h"
#include "solvers/fluid/density_rate.h"

namespace upf {

// The predicted density rho_adv_i of either solver (see the header) and K_i from it; K_i is
// also added to `k_total` (reactions on bodies, the exported pressure) and, scaled to be
// independent of dt, to `stiffness` (the warm start of the next step).
struct DfsphStiffnessStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Real* boundary_divergence;
  const Real* density;
  const Real* factor;
  const Vec3* v;
  Real dt;
  Real omega;                    // relaxation of the Jacobi update
  bool divergence;               // the divergence-free solver, else the constant-density one
  std::uint32_t min_neighbours;  // divergence: particles with fewer are left alone
  Real* rho_adv;
  Real* k;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real rho0 = f.rest_density[f.material[i]];
    const Real rate =
        density_rate(f, fluid_gradient, boundary_gradient[i], boundary_divergence[i], v, i);
    Real adv;
    if (divergence) {
      const std::uint32_t count = (f.fluid.offsets[i + 1] - f.fluid.offsets[i]) +
                                  (f.boundary.offsets[i + 1] - f.boundary.offsets[i]);
      adv = rho0 + (count >= min_neighbours && rate > Real(0) ? dt * rate : Real(0));
    } else {
      adv = density[i] + dt * rate;
      if (adv < rho0) adv = rho0;
    }
    rho_adv[i] = adv;
    k[i] = omega * (adv - rho0) * factor[i] / (dt * dt);
  }
};

// Adds this iteration's K_i to the step's total and to the stored stiffness, K_i dt^power.
struct DfsphAccumulateStage {
  const Real* k;
  Real dt_power;  // dt^2 for the density solver, dt for the divergence solver
  Real* k_total;
  Real* stiffness;
  UPF_HD void operator()(std::uint32_t i) const {
    k_total[i] += k[i];
    stiffness[i] += k[i] * dt_power;
  }
};

// The warm start, where the predicted density rho_adv (before it) shows an error: half the
// stored stiffness of the previous step, K_i = S_i / (2 dt^power), which also restarts S_i from
// there (SPlisHSPlasH's DFSPH halves it the same way, so a stiffness that is no longer needed
// decays instead of adding up); elsewhere K_i = S_i = 0.
struct DfsphWarmStartStage {
  FluidView f;
  const Real* rho_adv;
  Real dt_power;
  Real* stiffness;
  Real* k;
  Real* k_total;
  UPF_HD void operator()(std::uint32_t i) const {
    const bool error = rho_adv[i] > f.rest_density[f.material[i]];
    const Real s = error ? Real(0.5) * stiffness[i] : Real(0);
    stiffness[i] = s;
    k[i] = s / dt_power;
    k_total[i] += k[i];
  }
};

// Zeroes the stored stiffness (no warm start).
struct ClearStiffnessStage {
  Real* stiffness;
  UPF_HD void operator()(std::uint32_t i) const { stiffness[i] = 0; }
};

// v_i -= dt [ sum_j m_j (K_i + K_j) grad W_ij + rho0_i (K_i + K_b) sum_b V_b grad W_ib ]; K of a
// particle the solver does not move is 0.
struct DfsphVelocityStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Real* k;
  Real dt;
  Vec3* v;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real ki = k[i];
    Vec3 a = boundary_pressure_acceleration(f, boundary_gradient[i], ki,
                                            mirrored_pressure_factor(f, FactorArray{k}, i), i);
    for (std::uint32_t n = f.fluid.offsets[i]; n < f.fluid.offsets[i + 1]; ++n) {
      const std::uint32_t j = f.fluid.indices[n];
      a -= fluid_gradient.at(f, i, n) * pressure_pair(f, i, j, ki, k[j]);
    }
    v[i] += a * dt;
  }
};

// The step's end: v = v*, x += v dt; the exported pressure p_i = K_i rho_i^2 (the pressure of
// the symmetric SPH form a_i = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad W_ij).
struct DfsphIntegrateStage {
  const Vec3* v_star;
  const Real* k_total;
  const Real* density;
  Real dt;
  Vec3* v;
  Vec3* x;
  Real* pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    v[i] = v_star[i];
    x[i] += v[i] * dt;
    pressure[i] = k_total[i] * density[i] * density[i];
  }
};

// The pressure factor P_i of boundary_reactions.h: the step's total K_i.
struct TotalStiffness {
  static constexpr bool kPerDensitySquared = true;
  const Real* k_total;
  UPF_HD Real operator()(std::uint32_t i) const { return k_total[i]; }
};

}  // namespace upf
