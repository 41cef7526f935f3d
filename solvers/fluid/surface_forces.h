// Surface tension and adhesion shared by every fluid solver: Akinci, Akinci & Teschner 2013
// ("Versatile surface tension and adhesion for SPH fluids", ACM TOG 32(6) 182), with the kernels
// of akinci_kernels.h and H the support radius:
//   normal (eq. 4)     n_i = H sum_j (m_j / rho0_j) grad W_ij   (density_and_gradients, with the
//                      rest volumes: the paper's m_j / rho_j would need a pass after the densities)
//   tension (eq. 1-5)  F_ij = K_ij [ -gamma m_i m_j C(r) x_ij / r  - gamma m_i (n_i - n_j) ],
//                      K_ij = 2 rho0 / (rho_i + rho_j),  r = |x_ij|
//   adhesion (eq. 6)   F_ib = -beta m_i Psi_b A(|x_ib|) x_ib / |x_ib|,  Psi_b = rho0_i V_b
// written as accelerations. Symmetric in every pair, so liquid and bodies together keep their
// momentum (the reaction of adhesion on rigid particles is in boundary_reactions.h):
//   - two materials use the mean of their gamma and their mean rest density in K_ij;
//   - the curvature term weighs the pair by the reduced mass 2 m_i m_j / (m_i + m_j), which is
//     Akinci's m_i when the masses are equal and keeps Newton's third law when they are not.
// C++17 and UPF_HD: the device pipeline runs the same functions.
#pragma once

#include "solvers/fluid/akinci_kernels.h"
#include "solvers/fluid/continuum_surface_force.h"
#include "solvers/fluid/fluid_view.h"

namespace upf {

// Cohesion and curvature on liquid particle i, as an acceleration.
UPF_HD inline Vec3 akinci_tension_acceleration(const FluidView& f, const Real* density,
                                               std::uint32_t i) {
  const SurfaceForceView& s = f.surface;
  const Real h = f.kernel.support_radius();
  const AkinciCohesionKernel cohesion(h);
  const Vec3 xi = f.x[i];
  const MaterialId mat_i = f.material[i];
  const Real gamma_i = s.cohesion[mat_i];
  const Real rho0_i = f.rest_density[mat_i];
  const Real mi = f.mass[i];
  const Real rho_i = density[i];
  Vec3 a{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const MaterialId mat_j = f.material[j];
    const Real gamma = Real(0.5) * (gamma_i + s.cohesion[mat_j]);
    if (gamma <= 0) continue;
    const Vec3 xij = xi - f.x[j];
    const Real r = norm(xij);
    if (r <= Real(1e-9) * h) continue;  // i itself (no pair force), or a coincident particle
    // One division for K_ij gamma (rho0_i + rho0_j) / (rho_i + rho_j), the reduced-mass factor
    // 2 m_j / (m_i + m_j) and the cohesion's 1 / r.
    const Real mj = f.mass[j];
    const Real scale =
        gamma * (rho0_i + f.rest_density[mat_j]) * mj / ((rho_i + density[j]) * (mi + mj) * r);
    a -= (s.normal[i] - s.normal[j]) * (scale * Real(2) * r) +
         xij * (scale * (mi + mj) * cohesion.value(r));
  }
  return a;
}

// Adhesion of liquid particle i to its boundary neighbours (eq. 6), as an acceleration: every
// model's wetting.
UPF_HD inline Vec3 akinci_adhesion_acceleration(const FluidView& f, std::uint32_t i) {
  const SurfaceForceView& s = f.surface;
  const Real h = f.kernel.support_radius();
  const AkinciAdhesionKernel adhesion(h);
  const Vec3 xi = f.x[i];
  const MaterialId mi = f.material[i];
  Vec3 a{};
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    const Real beta = s.adhesion_between(mi, f.material[b]);
    if (beta <= 0) continue;
    const Vec3 xib = xi - f.x[b];
    const Real r = norm(xib);
    if (r <= Real(1e-9) * h) continue;
    a -= xib * (beta * f.boundary_volume[b] * adhesion.value(r) / r);
  }
  return a * f.rest_density[mi];
}

// The surface forces on liquid particle i, as an acceleration: the model's tension, then adhesion.
UPF_HD inline Vec3 surface_acceleration(const FluidView& f, const Real* density, std::uint32_t i) {
  Vec3 a = f.surface.model == SurfaceTensionModel::ContinuumSurfaceForce
               ? csf_tension_acceleration(f, i)
               : akinci_tension_acceleration(f, density, i);
  if (f.surface.has_adhesion) a += akinci_adhesion_acceleration(f, i);
  return a;
}

// The force liquid particle i's adhesion puts on boundary particle b: the opposite of i's,
// beta m_i Psi_b A(r) x_ib / r (boundary_reactions.h gathers it over b's liquid neighbours).
UPF_HD inline Vec3 akinci_adhesion_reaction(const FluidView& f, std::uint32_t i, std::uint32_t b) {
  const SurfaceForceView& s = f.surface;
  const MaterialId mi = f.material[i];
  const Real beta = s.adhesion_between(mi, f.material[b]);
  if (beta <= 0) return {};
  const Real h = f.kernel.support_radius();
  const Vec3 xib = f.x[i] - f.x[b];
  const Real r = norm(xib);
  if (r <= Real(1e-9) * h) return {};
  const Real a = AkinciAdhesionKernel(h).value(r);
  return xib * (beta * f.mass[i] * f.rest_density[mi] * f.boundary_volume[b] * a / r);
}

}  // namespace upf
