// The per-particle functions of PCISPH (Solenthaler & Pajarola 2009), written once for host and
// device: the pressure acceleration and the predicted state.
#pragma once

#include "solvers/fluid/fluid_view.h"

namespace upf {

// Pressure acceleration of fluid particle i at the current positions, with the paper's symmetric
// form and rest densities in the denominators (as in the derivation of delta):
//   a_i = -sum_j m_j (p_i/rho0_i^2 + p_j/rho0_j^2) grad W_ij
//         -sum_b Psi_b (p_i/rho0_i^2) grad W_ib          (Akinci et al. 2012, eq. 10)
// The boundary term takes the fluid particle's own pressure (Akinci's eq. 10). The symmetric
// "mirrored" variant with 2 p_i drove the correction loop into slow, oscillating convergence next
// to walls (73 iterations on the first step of the hydrostatic tank instead of 3).
// `fluid_gradient` and `boundary_gradient` (sum_b V_b grad W_ib) come from density_and_gradients:
// the positions do not move during the correction loop, so neither do the gradients.
UPF_HD inline Vec3 pcisph_pressure_acceleration(const FluidView& f, const Real* pressure,
                                                const Vec3* fluid_gradient,
                                                const Vec3& boundary_gradient, std::uint32_t i) {
  const Real rho0 = f.rest_density[f.material[i]];
  const Real pi = pressure[i] / (rho0 * rho0);
  Vec3 a{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const Real rho0j = f.rest_density[f.material[j]];
    a -= fluid_gradient[k] * (f.mass[j] * (pi + pressure[j] / (rho0j * rho0j)));
  }
  // Psi_b p_i / rho0^2 = V_b rho0 p_i / rho0^2.
  a -= boundary_gradient * (rho0 * pi);
  return a;
}

}  // namespace upf
