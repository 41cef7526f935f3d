// Liquids of different rest density in one solve: the number-density formulation of Solenthaler
// & Pajarola 2008 ("Density contrast SPH interfaces", SCA 2008). Standard SPH sums neighbours'
// masses, rho_i = sum_j m_j W_ij, so a light particle next to heavy ones reads their mass as its
// own compression and its pressure pushes the interface apart (a false interface tension; the
// paper's Fig. 2, docs/multiphase.md has upf's numbers). The paper sums the particle number
// density delta_i = sum_j W_ij instead and takes rho_i = m_i delta_i, and applies the pressure
// with the volumes 1/delta (its eq. 8):
//   F_i = -sum_j (p_i / delta_i^2 + p_j / delta_j^2) grad W_ij.
// Every solver here writes its pressure term as a_i = -sum_j m_j (P_i + P_j) grad W_ij with a
// pressure factor P = p / rho^2 (PCISPH: p / rho0^2, DFSPH: K); with delta = rho / m the paper's
// force divided by m_i is
//   a_i = -sum_j (m_i P_i + (m_j^2 / m_i) P_j) grad W_ij,
// which is the standard term when the masses are equal, and stays antisymmetric (m_i a_i =
// -m_j a_j per pair), so momentum is kept. Boundaries are unchanged: Akinci et al. 2012's
// Psi_b = rho0_i V_b already is a volume times the liquid's own density.
// The solvers take these forms when the scene's liquids differ in rest density
// (FluidView::density_contrast); otherwise the standard sums run, bit for bit as before.
#pragma once

#include "solvers/fluid/fluid_view.h"

namespace upf {

// The mass of neighbour j in particle i's density sum: m_j, or m_i with density contrast.
UPF_HD inline Real density_weight(const FluidView& f, std::uint32_t i, std::uint32_t j) {
  return f.density_contrast ? f.mass[i] : f.mass[j];
}

// The pair's pressure coefficient c with a_i = -sum_j c grad W_ij, from the pressure factors
// P_i, P_j (see the header): m_j (P_i + P_j), or m_i P_i + (m_j^2 / m_i) P_j with density contrast.
UPF_HD inline Real pressure_pair(const FluidView& f, std::uint32_t i, std::uint32_t j, Real pi,
                                 Real pj) {
  if (!f.density_contrast) return f.mass[j] * (pi + pj);
  const Real mi = f.mass[i], mj = f.mass[j];
  return mi * pi + mj * (mj / mi) * pj;
}

// The share of pair (i, j) in the diagonal D_i of density_rate.h, from g = w_ij grad W_ij
// (w_ij = density_weight): |g|^2 m_i / m_j with density contrast (sum_j w_ij beta_ji |grad W|^2,
// beta_ji = m_i^2 / m_j the weight of K_i in j's pressure term), else |g|^2, the equal-mass form.
UPF_HD inline Real diagonal_pair(const FluidView& f, std::uint32_t i, std::uint32_t j,
                                 const Vec3& g) {
  const Real g2 = squared_norm(g);
  return f.density_contrast ? g2 * (f.mass[i] / f.mass[j]) : g2;
}

}  // namespace upf
