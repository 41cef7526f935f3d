// The per-particle functions of WCSPH (Becker & Teschner 2007, "Weakly compressible SPH for free
// surface flows", SCA 2007), written once for host and device. Kernel gradients are the cubic
// spline's, taken from density_and_gradients like PCISPH's.
#pragma once

#include "solvers/fluid/boundary_pressure.h"
#include "solvers/fluid/density_contrast.h"
#include "solvers/fluid/fluid_view.h"

namespace upf {

// The Tait equation (paper eq. 6, gamma = 7), clamped at zero (see wcsph_solver.h):
//   p = B ((rho / rho0)^7 - 1),  B = rho0 c^2 / 7.
UPF_HD inline Real tait_pressure(Real rho, Real rest_density, Real b) {
  const Real r = rho / rest_density;
  const Real r2 = r * r;
  const Real p = b * (r2 * r2 * r2 * r - Real(1));
  return p > 0 ? p : Real(0);
}

// Pressure acceleration, the paper's symmetric form (eq. 5):
//   a_i = -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad W_ij
//         -sum_b Psi_b (p_i + p_b) / rho_i^2 grad W_ib    (boundary_pressure.h)
// `boundary_gradient` is sum_b V_b grad W_ib; Psi_b = rho0_i V_b. Where liquids differ in rest
// density, the pair term of density_contrast.h.
UPF_HD inline Vec3 wcsph_pressure_acceleration(const FluidView& f, const Real* density,
                                               const Real* pressure, FluidGradients fluid_gradient,
                                               const Vec3& boundary_gradient, std::uint32_t i) {
  const Real rho = density[i];
  const Real pi = pressure[i] / (rho * rho);
  Vec3 a{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    a -= fluid_gradient.at(f, i, k) *
         pressure_pair(f, i, j, pi, pressure[j] / (density[j] * density[j]));
  }
  const Real pb = mirrored_pressure_factor(f, PressureOverDensitySquared{pressure, density, 1}, i);
  return a + boundary_pressure_acceleration(f, boundary_gradient, pi, pb, i);
}

// The paper's artificial viscosity (eq. 11), acting only between approaching particles:
//   a_i = -sum_j m_j Pi_ij grad W_ij,
//   Pi_ij = -nu min(v_ij . x_ij, 0) / (|x_ij|^2 + 0.01 h^2),  nu = 2 alpha h c / (rho_i + rho_j),
// with h the smoothing length, H / 2. `two_alpha_h_c` = 2 alpha h c.
UPF_HD inline Vec3 artificial_viscosity_acceleration(const FluidView& f, const Real* density,
                                                     FluidGradients fluid_gradient,
                                                     Real two_alpha_h_c, std::uint32_t i) {
  const Real h = Real(0.5) * f.kernel.support_radius();
  const Vec3 xi = f.x[i];
  const Vec3 vi = f.v[i];
  Vec3 a{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const Vec3 xij = xi - f.x[j];
    const Real vx = dot(vi - f.v[j], xij);
    if (vx >= 0) continue;
    const Real nu = two_alpha_h_c / (density[i] + density[j]);
    const Real pi_ij = -nu * vx / (squared_norm(xij) + Real(0.01) * h * h);
    a -= fluid_gradient.at(f, i, k) * (f.mass[j] * pi_ij);
  }
  return a;
}

// p_i from the Tait equation, with B = rho0 c^2 / 7 per material.
struct TaitPressureStage {
  FluidView f;
  const Real* density;
  const Real* tait_factor;  // per material
  Real* pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    const MaterialId m = f.material[i];
    pressure[i] = tait_pressure(density[i], f.rest_density[m], tait_factor[m]);
  }
};

struct WcsphPressureAccelerationStage {
  FluidView f;
  const Real* density;
  const Real* pressure;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  Vec3* a_pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    a_pressure[i] =
        wcsph_pressure_acceleration(f, density, pressure, fluid_gradient, boundary_gradient[i], i);
  }
};

// Adds the artificial viscosity to a_other.
struct ArtificialViscosityStage {
  FluidView f;
  const Real* density;
  FluidGradients fluid_gradient;
  Real two_alpha_h_c;
  Vec3* a_other;
  UPF_HD void operator()(std::uint32_t i) const {
    a_other[i] += artificial_viscosity_acceleration(f, density, fluid_gradient, two_alpha_h_c, i);
  }
};

}  // namespace upf
