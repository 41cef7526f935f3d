// The per-particle functions of Position Based Fluids (Macklin & Müller 2013, "Position Based
// Fluids", ACM TOG 32(4), SIGGRAPH 2013), written once for host and device (UPF_HD, C++17).
//
// Units. The paper takes every particle's mass as 1; here masses are real (m = rho0 h^3) and the
// constraint gradients carry them, with the position-based-dynamics weights w = 1/m:
//   C_i        = rho_i / rho0_i - 1                                              (eq. 1)
//   rho_i      = sum_j m_j W(x_i - x_j) + sum_b rho0_i V_b W(x_i - x_b)  (Akinci et al. 2012)
//   grad_i C_i = sum_j V_j grad W_ij + sum_b V_b grad W_ib,   V_j = m_j / rho0_i  (eq. 8, k = i)
//   grad_j C_i = -V_j grad W_ij                                                  (eq. 8, k = j)
//   lambda_i   = -C_i / (|grad_i C_i|^2 + sum_j V_i V_j |grad W_ij|^2 + eps)      (eq. 11)
//   dx_i       = sum_j (V_j lambda_i + V'_j lambda_j + V_j s_corr) grad W_ij
//                + lambda_i sum_b V_b grad W_ib,    V'_j = m_j / rho0_j          (eq. 12, 14)
// lambda here is the paper's lambda in m^2 (the PBD multiplier divided by the particle mass); for
// equal masses V_j = 1/rho0 of the paper and every formula reduces to the paper's. Boundary
// particles have w = 0: they count in the density and the gradient, but are never moved.
#pragma once

#include "solvers/fluid/fluid_view.h"

namespace upf::pbf {

// Constants of one step, in SI units, prepared by PbfSolver from its parameters.
struct PbfConstants {
  Real relaxation = 0;             // eps of eq. 11 [1/m^2]
  Real tensile_scale = 0;          // k of eq. 13, as a lambda [m^2]
  Real tensile_inv_reference = 0;  // 1 / W(dq) [m^3]
  int tensile_exponent = 4;        // n of eq. 13
  bool unilateral = true;          // C_i = max(C_i, 0)
};

// Artificial pressure (eq. 13): s_corr = -k (W(r) / W(dq))^n, a lambda [m^2].
UPF_HD inline Real pbf_tensile_correction(const PbfConstants& c, Real w) {
  const Real ratio = w * c.tensile_inv_reference;
  Real power = 1;
  for (int e = 0; e < c.tensile_exponent; ++e) power *= ratio;
  return -c.tensile_scale * power;
}

// What the lambda pass of an iteration leaves for the correction pass, so that the latter
// evaluates no kernel: both run at the same predicted positions.
struct PbfPairTerms {
  Vec3* fluid_gradient = nullptr;     // grad W_ij per fluid-list slot
  Real* tensile = nullptr;            // s_corr per fluid-list slot [m^2]
  Vec3* boundary_gradient = nullptr;  // per particle: sum_b V_b grad W_ib
  Real* density = nullptr;            // per particle: rho_i
};

// lambda_i (eq. 11) at the predicted positions `xs` (boundary particles' included: a moving
// body is seen where it will be); fills i's entries of `terms`.
UPF_HD inline Real pbf_lambda(const FluidView& f, const Vec3* xs, const PbfConstants& c,
                              const PbfPairTerms& terms, std::uint32_t i) {
  const Vec3 xi = xs[i];
  const Real rho0 = f.rest_density[f.material[i]];
  const Real vi = f.mass[i] / rho0;
  Real rho = f.mass[i] * f.kernel.value(Real(0));
  Vec3 grad_fluid{};
  Real sum_grad_j2 = 0;  // sum_j V_i V_j |grad W_ij|^2: the neighbours' share of the denominator
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    Vec3 g;
    const Real w = f.kernel.value_and_gradient(xi - xs[j], g);
    rho += f.mass[j] * w;
    const Real vj = f.mass[j] / rho0;
    grad_fluid += g * vj;
    sum_grad_j2 += vi * vj * squared_norm(g);
    terms.fluid_gradient[k] = g;
    terms.tensile[k] = pbf_tensile_correction(c, w);
  }
  Vec3 grad_boundary{};
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    Vec3 g;
    rho += rho0 * f.boundary_volume[b] * f.kernel.value_and_gradient(xi - xs[b], g);
    grad_boundary += g * f.boundary_volume[b];
  }
  terms.boundary_gradient[i] = grad_boundary;
  terms.density[i] = rho;
  Real constraint = rho / rho0 - Real(1);
  if (c.unilateral && constraint < 0) constraint = 0;
  const Real denominator = squared_norm(grad_fluid + grad_boundary) + sum_grad_j2 + c.relaxation;
  return -constraint / denominator;
}

// dx_i (eqs. 12 and 14): the Jacobi position correction of particle i from the lambdas of the
// current iteration and the pair terms of its lambda pass.
UPF_HD inline Vec3 pbf_position_correction(const FluidView& f, const Real* lambda,
                                           const PbfPairTerms& terms, std::uint32_t i) {
  const Real rho0 = f.rest_density[f.material[i]];
  const Real li = lambda[i];
  Vec3 dx{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const Real vj = f.mass[j] / rho0;
    const Real vj_own = f.mass[j] / f.rest_density[f.material[j]];
    dx += terms.fluid_gradient[k] * (vj * (li + terms.tensile[k]) + vj_own * lambda[j]);
  }
  return dx + terms.boundary_gradient[i] * li;
}

UPF_HD constexpr Vec3 pbf_cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// What the velocity pass reads from the neighbours' new velocities, in one loop over them.
struct PbfVelocityTerms {
  Vec3 xsph;   // velocity after XSPH viscosity [m/s]
  Vec3 omega;  // vorticity [1/s]
};

// XSPH viscosity (eq. 17, Monaghan 1989 with the volumes the paper's unit masses leave out),
//   v_i + c sum_j V_j (v_j - v_i) W_ij,
// a blend towards the neighbours' velocities, and the vorticity (eq. 15) as the SPH curl
//   omega_i = sum_j V_j grad W_ij x (v_j - v_i).
// Fluid neighbours only.
UPF_HD inline PbfVelocityTerms pbf_velocity_terms(const FluidView& f, Real c, std::uint32_t i) {
  const Vec3 xi = f.x[i];
  const Vec3 vi = f.v[i];
  Vec3 blend{}, omega{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const Real vj = f.mass[j] / f.rest_density[f.material[j]];
    const Vec3 dv = f.v[j] - vi;
    Vec3 g;
    const Real w = f.kernel.value_and_gradient(xi - f.x[j], g);
    blend += dv * (vj * w);
    omega += pbf_cross(g, dv) * vj;
  }
  return {vi + blend * c, omega};
}

// Vorticity confinement acceleration (eq. 16): epsilon (N x omega_i), N = eta / |eta|,
// eta = grad |omega| = sum_j V_j (|omega_j| - |omega_i|) grad W_ij. It points towards stronger
// vorticity, so the acceleration feeds back the rotation that damping removed (Fedkiw et al.
// 2001). `epsilon` in m/s.
UPF_HD inline Vec3 pbf_vorticity_acceleration(const FluidView& f, const Vec3* omega, Real epsilon,
                                              std::uint32_t i) {
  const Vec3 xi = f.x[i];
  const Real wi = norm(omega[i]);
  Vec3 eta{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const Real vj = f.mass[j] / f.rest_density[f.material[j]];
    eta += f.kernel.gradient(xi - f.x[j]) * (vj * (norm(omega[j]) - wi));
  }
  const Real eta_norm = norm(eta);
  if (!(eta_norm > Real(0))) return {};
  return pbf_cross(eta / eta_norm, omega[i]) * epsilon;
}

}  // namespace upf::pbf
