// The per-particle functions and stages of PCISPH (Solenthaler & Pajarola 2009), written once for
// host and device: the predicted state, the pressure correction and the pressure acceleration.
#pragma once

#include "solvers/fluid/boundary_pressure.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_view.h"

namespace upf {

// Pressure acceleration of fluid particle i at the current positions, with the paper's symmetric
// form and rest densities in the denominators (as in the derivation of delta):
//   a_i = -sum_j m_j (P_i + P_j) grad W_ij - sum_b Psi_b (p_i + p_b)/rho0_i^2 grad W_ib,
// P = p / rho0^2 (`scaled_pressure`, written beside p by the correction so that no pair divides;
// boundary_pressure.h for the walls, density_contrast.h's pair term where liquids differ in rest
// density). `fluid_gradient` and `boundary_gradient` (sum_b V_b grad W_ib) come from
// density_and_gradients: the positions do not move during the correction loop, so neither do the
// gradients.
UPF_HD inline Vec3 pcisph_pressure_acceleration(const FluidView& f, const Real* pressure,
                                                const Real* scaled_pressure,
                                                FluidGradients fluid_gradient,
                                                const Vec3& boundary_gradient, std::uint32_t i) {
  const Real pi = scaled_pressure[i];
  Vec3 a{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    a -= fluid_gradient.at(f, i, k) * pressure_pair(f, i, j, pi, scaled_pressure[j]);
  }
  const Real pb = mirrored_pressure_factor(
      f, PressureOverRestDensitySquared{pressure, f.rest_density, f.material}, i);
  return a + boundary_pressure_acceleration(f, boundary_gradient, pi, pb, i);
}

// The prediction (docs/solvers.md, PCISPH step 2): v* = v + (a_other + a_p) dt, x* = x + v* dt.
struct PcisphPredictStage {
  FluidView f;
  const Vec3* a_other;
  const Vec3* a_pressure;
  Real dt;
  Vec3* x_star;
  UPF_HD void operator()(std::uint32_t i) const {
    const Vec3 v_star = f.v[i] + (a_other[i] + a_pressure[i]) * dt;
    x_star[i] = f.x[i] + v_star * dt;
  }
};

// Loop step 1: rho* at the predicted positions, and with density contrast fluid_density's ratio
// r_i (kept for the correction of step 4, which the stopping tests may skip).
struct PcisphPredictedDensityStage {
  FluidView f;
  const Vec3* x_star;
  Real* rho_star;
  Real* contrast_ratio;  // null without density contrast
  UPF_HD void operator()(std::uint32_t i) const {
    rho_star[i] = fluid_density(f, x_star, i, contrast_ratio ? contrast_ratio + i : nullptr);
  }
};

// Loop step 4: p += delta (rho* - rho0), clamped at 0, and P = p / rho0^2 for the acceleration.
// With density contrast delta / r_i (fluid_density's ratio): delta is the inverse of the diagonal
// of the pressure-to-density map on a one-liquid lattice, where the neighbours' share dominates.
// A neighbour j moves by p_i / rho0_j, so that diagonal grows by about r_i (exactly, with
// |grad W_ij|^2 for the weights; W_ij, which the density sum has at hand, held the same tanks): a
// heavy particle among light ones (r = 5.5 at a ratio of 10, half its neighbours light)
// over-corrected its error five-fold and PCISPH diverged at the interface (docs/multiphase.md).
struct PcisphCorrectPressureStage {
  FluidView f;
  const Real* rho_star;
  const Real* contrast_ratio;  // null without density contrast
  Real delta;
  Real* pressure;
  Real* scaled_pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real rho0 = f.rest_density[f.material[i]];
    // delta / 1 is delta: one liquid runs bit for bit as without contrast
    const Real ratio = contrast_ratio ? contrast_ratio[i] : Real(1);
    const Real p = pressure[i] + delta / ratio * (rho_star[i] - rho0);
    pressure[i] = p > 0 ? p : Real(0);
    scaled_pressure[i] = pressure[i] / (rho0 * rho0);
  }
};

// Loop step 5: the pressure acceleration from the new pressures.
struct PcisphPressureAccelerationStage {
  FluidView f;
  const Real* pressure;
  const Real* scaled_pressure;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  Vec3* a_pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    a_pressure[i] = pcisph_pressure_acceleration(f, pressure, scaled_pressure, fluid_gradient,
                                                 boundary_gradient[i], i);
  }
};

// Loop step 5 and the next prediction in one pass: the prediction needs the particle's own new
// acceleration only, so it needs no pass of its own.
struct PcisphAccelerateAndPredictStage {
  PcisphPressureAccelerationStage accelerate;
  PcisphPredictStage predict;
  UPF_HD void operator()(std::uint32_t i) const {
    accelerate(i);
    predict(i);
  }
};

}  // namespace upf
