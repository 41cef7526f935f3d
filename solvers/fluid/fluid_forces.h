// Per-particle pieces shared by every fluid solver, so that comparing solvers isolates the
// pressure solver.
//
// Density: SPH summation over fluid neighbours plus the boundary term of Akinci et al. 2012,
//   rho_i = sum_j m_j W_ij + sum_b Psi_b W_ib,  Psi_b = rho0_i V_b,
//   with m_i for m_j where liquids differ in rest density (density_contrast.h).
// Viscosity: the Laplacian approximation of Monaghan 2005 ("Smoothed particle hydrodynamics",
//   Rep. Prog. Phys. 68, eq. 6.1 form used with a kinematic viscosity nu):
//   a_i = F nu sum_j (m_j / rho_j) (v_ij . x_ij) / (|x_ij|^2 + 0.01 H^2) grad W_ij,
//   and the same against boundary particles with Psi_b / rho_i and nu_boundary; F is the
//   paper's 2 (d + 2) calibrated on the particle lattice (viscosity_operator.h).
#pragma once

#include "solvers/fluid/density_contrast.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/kernel_sum.h"
#include "solvers/fluid/wall_velocity.h"

namespace upf {

// Density of fluid particle i, with every position taken from `xf` (current or predicted; a
// moving boundary must be predicted too, or an approaching body is seen a step late and runs
// fluid over). With `contrast_ratio` not null (density contrast), also PCISPH's
//   r_i = sum_j (rho0_i / rho0_j) W_ij / sum_j W_ij   (1 without neighbours; pcisph_kernels.h).
UPF_HD inline Real fluid_density(const FluidView& f, const Vec3* xf, std::uint32_t i,
                                 Real* contrast_ratio = nullptr) {
  const Vec3 xi = xf[i];
  const Real rho0 = f.rest_density[f.material[i]];
  Real rho = f.mass[i] * f.kernel.value(Real(0));
  const std::uint32_t begin = f.fluid.offsets[i], end = f.fluid.offsets[i + 1];
  if (!f.density_contrast) {
    rho += kernel_sum(f.kernel, xi, xf, f.fluid.indices, begin, end, ArrayWeight{f.mass});
  } else {
    Real kernel_total = 0, weighted = 0;
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t j = f.fluid.indices[k];
      const Real w = f.kernel.value(xi - xf[j]);
      rho += density_weight(f, i, j) * w;
      kernel_total += w;
      weighted += w * (rho0 / f.rest_density[f.material[j]]);
    }
    if (contrast_ratio)
      *contrast_ratio = kernel_total > Real(0) ? weighted / kernel_total : Real(1);
  }
  if (contrast_ratio && !f.density_contrast) *contrast_ratio = 1;
  return rho + rho0 * kernel_sum(f.kernel, xi, xf, f.boundary.indices, f.boundary.offsets[i],
                                 f.boundary.offsets[i + 1], ArrayWeight{f.boundary_volume});
}

// Density at the current positions and the kernel gradients there, in one pass: grad W_ij goes
// into the store of `fluid_gradient` (if it has one) for each fluid-list slot k of i and
// sum_b V_b grad W_ib into boundary_gradient. The gradients are reused by every force of the step.
// With `normal` not null, also Akinci et al. 2013's surface normal n_i = H sum_j V_j grad W_ij
// (surface_forces.h) with the neighbours' rest volumes V_j = m_j / rho0_j, in the same pass: the
// current densities would need a pass of their own.
UPF_HD inline Real density_and_gradients(const FluidView& f, FluidGradients fluid_gradient,
                                         Vec3& boundary_gradient, std::uint32_t i,
                                         Vec3* normal = nullptr) {
  const Vec3 xi = f.x[i];
  Real rho = f.mass[i] * f.kernel.value(Real(0));
  Vec3 n{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    Vec3 g;
    rho += density_weight(f, i, j) * f.kernel.value_and_gradient(xi - f.x[j], g);
    if (fluid_gradient.stored) fluid_gradient.stored[k] = g;
    if (normal) n += g * (f.mass[j] / f.rest_density[f.material[j]]);
  }
  if (normal) *normal = n * f.kernel.support_radius();
  const Real rho0 = f.rest_density[f.material[i]];
  Vec3 boundary{};
  Real boundary_density = 0;
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    Vec3 g;
    const Real w = f.kernel.value_and_gradient(xi - f.x[b], g);
    boundary += g * f.boundary_volume[b];
    boundary_density += f.boundary_volume[b] * w;
  }
  boundary_gradient = boundary;
  return rho + rho0 * boundary_density;
}

// `fluid_gradient` as density_and_gradients left it this step. Zero with implicit viscosity
// (f.solved_velocity), whose solve adds its own (implicit_viscosity.h).
UPF_HD inline Vec3 viscosity_acceleration(const FluidView& f, const Real* density,
                                          FluidGradients fluid_gradient, std::uint32_t i) {
  if (f.solved_velocity) return Vec3{};
  const Real h2 = f.kernel.support_radius() * f.kernel.support_radius();
  const Vec3 xi = f.x[i];
  const Vec3 vi = f.v[i];
  Vec3 a{};
  const Real nu = f.viscosity[f.material[i]];
  if (nu > 0) {
    for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
      const std::uint32_t j = f.fluid.indices[k];
      const Vec3 xij = xi - f.x[j];
      const Real vx = dot(vi - f.v[j], xij);
      a += fluid_gradient.at(f, i, k) *
           (f.mass[j] / density[j] * vx / (squared_norm(xij) + Real(0.01) * h2));
    }
    a *= f.viscosity_factor * nu;
  }
  const Real nub = f.boundary_viscosity[f.material[i]];
  if (nub > 0) {
    const Real rho0 = f.rest_density[f.material[i]];
    Vec3 ab{};
    for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
      const std::uint32_t b = f.boundary.indices[k];
      const Vec3 xib = xi - f.x[b];
      const Real vx = dot(vi - viscous_wall_velocity(f, b), xib);
      ab += f.kernel.gradient(xib) *
            (rho0 * f.boundary_volume[b] / density[i] * vx / (squared_norm(xib) + Real(0.01) * h2));
    }
    a += ab * (f.viscosity_factor * nub);
  }
  return a;
}

}  // namespace upf
