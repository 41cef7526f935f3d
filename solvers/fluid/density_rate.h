// Pieces of the implicit pressure solvers (DFSPH, IISPH) that work on velocities: the density's
// rate of change at given velocities, the diagonal of the pressure system, a velocity kick.
// Host and device, C++17 (fluid_cuda_check.cu instantiates the stages).
//
// Drho_i/Dt = sum_j m_j (v_i - v_j) . grad W_ij + rho0_i sum_b V_b (v_i - v_b) . grad W_ib
// (Akinci et al. 2012 boundaries, Psi_b = rho0_i V_b). A pressure-like term K_i acting as
//   a_i = -sum_j m_j (K_i + K_j) grad W_ij - rho0_i K_i sum_b V_b grad W_ib
// changes particle i's density over a step by -dt^2 K_i D_i through its own K_i, with
//   D_i = |sum_j m_j grad W_ij + rho0_i sum_b V_b grad W_ib|^2 + sum_j m_i m_j |grad W_ij|^2
// (equal masses: the DFSPH paper's rho_i / alpha_i, and -rho_i^2 a_ii / dt^2 of IISPH). The
// wall's own pressure term, rho0_i K_b sum_b V_b grad W_ib (boundary_pressure.h), is a
// neighbourhood average of K and is left to the off-diagonal part. Where liquids differ in rest
// density, m_i stands for m_j in the sums and D_i follows (density_contrast.h).
#pragma once

#include "solvers/fluid/density_contrast.h"
#include "solvers/fluid/fluid_view.h"

namespace upf {

// 1 / D_i (0 where D_i vanishes: a particle with no neighbour is not corrected).
// `fluid_gradient` holds grad W_ij per fluid-list slot, `boundary_gradient` sum_b V_b grad W_ib.
struct InverseDiagonalStage {
  FluidView f;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  Real* inverse_diagonal;
  UPF_HD void operator()(std::uint32_t i) const {
    const Real rho0 = f.rest_density[f.material[i]];
    Vec3 sum = boundary_gradient[i] * rho0;
    Real sum_squares = 0;
    for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
      const std::uint32_t j = f.fluid.indices[k];
      const Vec3 g = fluid_gradient.at(f, i, k) * density_weight(f, i, j);
      sum += g;
      sum_squares += diagonal_pair(f, i, j, g);
    }
    const Real d = squared_norm(sum) + sum_squares;
    inverse_diagonal[i] = d > Real(0) ? Real(1) / d : Real(0);
  }
};

// sum_b V_b v_b . grad W_ib: the moving boundaries' part of Drho_i/Dt, fixed during a step.
struct BoundaryVelocityDivergenceStage {
  FluidView f;
  Real* boundary_divergence;
  UPF_HD void operator()(std::uint32_t i) const {
    Real sum = 0;
    for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
      const std::uint32_t b = f.boundary.indices[k];
      sum += f.boundary_volume[b] * dot(f.v[b], f.kernel.gradient(f.x[i] - f.x[b]));
    }
    boundary_divergence[i] = sum;
  }
};

// Drho_i/Dt at the velocities `v` (any particle's; boundaries through boundary_divergence).
UPF_HD inline Real density_rate(const FluidView& f, FluidGradients fluid_gradient,
                                const Vec3& boundary_gradient, Real boundary_divergence,
                                const Vec3* v, std::uint32_t i) {
  const Vec3 vi = v[i];
  Real rate = 0;
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    rate += density_weight(f, i, j) * dot(vi - v[j], fluid_gradient.at(f, i, k));
  }
  const Real rho0 = f.rest_density[f.material[i]];
  return rate + rho0 * (dot(vi, boundary_gradient) - boundary_divergence);
}

// v += a dt.
struct VelocityKickStage {
  const Vec3* a;
  Real dt;
  Vec3* v;
  UPF_HD void operator()(std::uint32_t i) const { v[i] += a[i] * dt; }
};

// Copies one scalar array into another (IISPH's last Jacobi buffer into the pressure field, DFSPH's
// density into the base its summed check re-bases).
struct CopyScalarStage {
  const Real* from;
  Real* to;
  UPF_HD void operator()(std::uint32_t i) const { to[i] = from[i]; }
};

// Copies every particle's velocity into a working array.
struct CopyVelocityStage {
  const Vec3* v;
  Vec3* v_work;
  UPF_HD void operator()(std::uint32_t i) const { v_work[i] = v[i]; }
};

}  // namespace upf
