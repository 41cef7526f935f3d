// Implicit viscosity after Weiler, Koschier, Brand & Bender 2018 ("A physically consistent
// implicit viscosity solver for SPH fluids", Computer Graphics Forum 37(2)): the viscous force of
// fluid_forces.h's Laplacian (Monaghan 2005, the form Weiler et al. use) is taken at the
// velocities of the end of the step (backward Euler), so the time step is no longer limited by
// dt <= 0.07 s^2 / nu (viscosity_operator.h). Per step, over the solver's liquid particles i,
//   m_i u_i - dt F_i(u) = m_i v*_i,   v*_i = v_i + dt a_other_i (gravity, surface forces, grains),
//   F_i(u) = sum_j c_ij grad W_ij (x_ij . (u_i - u_j)) + sum_b c_ib grad W_ib (x_ib . (u_i - v_b)),
//   c_ij = F mu_ij V_i V_j / (|x_ij|^2 + 0.01 H^2),  mu_ij = (nu_i rho0_i + nu_j rho0_j) / 2,
//   c_ib = F nu_b,i rho0_i V_i V_b / (|x_ib|^2 + 0.01 H^2),  V_i = m_i / rho_i,
// with F the paper's 2 (d + 2) calibrated on the lattice (viscosity_operator.h) and nu_b the
// liquid's boundary_viscosity against walls and bodies (their velocities v_b are known, so they go
// to the right-hand side).
//
// Where this differs from the paper, and why: Weiler et al. write each row per unit mass
// (coefficient m_j / rho_j, not symmetric between i and j unless all volumes are equal) and take
// a = (u - v*) / dt. Here each row is a momentum balance with the symmetric coefficient c_ij, so
// the matrix is symmetric positive definite (grad W_ij x_ij^T = W'/r x_ij x_ij^T, W' <= 0) and the
// conjugate gradient is the right method for it; and the force put on the particles is F_i at the
// solved u, whose pairs cancel exactly, so momentum is conserved whatever the solver's residual.
//
// The solve is a matrix-free conjugate gradient over the neighbour lists with a 3x3 block-Jacobi
// preconditioner, warm-started from the last step's viscous acceleration (a field, so reordering,
// ranks and checkpoints carry it). Its dot products are exact fixed-point sums
// (scaled_fixed_point_sum.h): the iteration count is the same for any thread count, backend and
// rank count. C++17: nvcc builds it (fluid_cuda_check.cu).
#pragma once

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>

#include "framework/executors/particle_range.h"
#include "framework/executors/scaled_fixed_point_sum.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"
#include "solvers/fluid/wall_velocity.h"

namespace upf {

// The solve's controls: the liquids' viscosity_tolerance (relative residual) and
// viscosity_max_iterations.
struct ImplicitViscositySettings {
  double tolerance = 1e-3;
  int max_iterations = 100;
};

// The arrays' field names, in the order of ImplicitViscosityArrays' members: FluidSolverState
// declares them (all but the last as per-step scratch), the device pipeline finds them by name.
inline constexpr int kImplicitViscosityFieldCount = 8;
inline constexpr const char* kImplicitViscosityFields[kImplicitViscosityFieldCount] = {
    "viscosity.solution",
    "viscosity.residual",
    "viscosity.search",
    "viscosity.product",
    "viscosity.preconditioned",
    "viscosity.inverse_diagonal",
    "viscosity.inverse_off_diagonal",
    "viscosity.acceleration"};

// Per particle arrays, fields of the particles (ghosts carry them; ghost refreshes follow every
// stage on a split world). `warm` holds the last step's viscous acceleration across steps.
struct ImplicitViscosityArrays {
  Vec3* solution;          // u: the velocities solved for (known ones for the particles not solved)
  Vec3* residual;          // r = b - A u
  Vec3* search;            // p, zero outside the solved particles
  Vec3* product;           // A p; before the first iteration F_i(u) of the warm start
  Vec3* preconditioned;    // z = D^-1 r
  Vec3* inverse_diagonal;  // D_i^-1, the symmetric block's xx, yy, zz
  Vec3* inverse_off_diagonal;  // and its xy, xz, yz
  Vec3* warm;                  // a_visc of the last step (in), of this step (out)
};

// The arrays from the fields' storage, `field(name)` giving each field's first element.
template <class FieldOf>
ImplicitViscosityArrays implicit_viscosity_arrays(FieldOf&& field) {
  const char* const* n = kImplicitViscosityFields;
  return {field(n[0]), field(n[1]), field(n[2]), field(n[3]),
          field(n[4]), field(n[5]), field(n[6]), field(n[7])};
}

// What run_non_pressure_stages needs for the solve (fluid_stages.h): null arrays, no solve.
struct ImplicitViscosityStep {
  const ImplicitViscosityArrays* arrays = nullptr;
  ImplicitViscositySettings settings{};
  OwnedMaterials owns{};
  std::size_t all = 0;  // every particle
  Real dt = 0;
};

struct ImplicitViscosityStats {
  int iterations = 0;
  double residual = 0;  // |r|_{D^-1} / |b|_{D^-1} at the end
  bool converged = true;
};

namespace implicit_viscosity_detail {

UPF_HD inline Real pair_denominator(const Vec3& r, Real h2) {
  return squared_norm(r) + Real(0.01) * h2;
}

// The viscous force on i at velocities u (F_i above); the boundary particles' velocities are
// their own with `boundary_moves`, zero without (the homogeneous part, for A p). With `block`
// not null, also -sum c grad W x^T, the derivative of F_i by u_i, as xx, yy, zz and xy, xz, yz.
UPF_HD inline Vec3 viscous_force(const FluidView& f, const Real* density, FluidGradients gradient,
                                 const Vec3* u, bool boundary_moves, std::uint32_t i,
                                 Vec3* block_diagonal = nullptr, Vec3* block_off = nullptr) {
  const Real h2 = f.kernel.support_radius() * f.kernel.support_radius();
  const MaterialId mi = f.material[i];
  const Real rho0 = f.rest_density[mi];
  const Real mu_i = f.viscosity[mi] * rho0;
  const Real volume_i = f.mass[i] / density[i];
  const Vec3 xi = f.x[i];
  const Vec3 ui = u[i];
  Vec3 force{}, diag{}, off{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const MaterialId mj = f.material[j];
    const Real mu = Real(0.5) * (mu_i + f.viscosity[mj] * f.rest_density[mj]);
    const Vec3 xij = xi - f.x[j];
    const Real c =
        f.viscosity_factor * mu * volume_i * (f.mass[j] / density[j]) / pair_denominator(xij, h2);
    const Vec3 g = gradient.at(f, i, k) * c;
    force += g * dot(xij, ui - u[j]);
    if (block_diagonal) {
      diag += Vec3{g.x * xij.x, g.y * xij.y, g.z * xij.z};
      off += Vec3{g.x * xij.y, g.x * xij.z, g.y * xij.z};
    }
  }
  const Real nub = f.boundary_viscosity[mi];
  if (nub > 0) {
    const Real scale = f.viscosity_factor * nub * rho0 * volume_i;
    for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
      const std::uint32_t b = f.boundary.indices[k];
      const Vec3 xib = xi - f.x[b];
      const Real c = scale * f.boundary_volume[b] / pair_denominator(xib, h2);
      const Vec3 g = f.kernel.gradient(xib) * c;
      force += g * dot(xib, boundary_moves ? ui - viscous_wall_velocity(f, b) : ui);
      if (block_diagonal) {
        diag += Vec3{g.x * xib.x, g.y * xib.y, g.z * xib.z};
        off += Vec3{g.x * xib.y, g.x * xib.z, g.y * xib.z};
      }
    }
  }
  if (block_diagonal) {
    *block_diagonal = diag;
    *block_off = off;
  }
  return force;
}

// D^-1 r for the symmetric block D (diagonal d: xx, yy, zz; off o: xy, xz, yz), by cofactors.
UPF_HD inline Vec3 apply_inverse(const Vec3& d, const Vec3& o, const Vec3& r) {
  return {d.x * r.x + o.x * r.y + o.y * r.z, o.x * r.x + d.y * r.y + o.z * r.z,
          o.y * r.x + o.z * r.y + d.z * r.z};
}

}  // namespace implicit_viscosity_detail

// u = v + dt (a_other + a_visc of the last step) for the solved particles (the warm start), u = v
// for every other particle (their velocities are known); p = 0 everywhere.
struct ViscosityStartStage {
  FluidView f;
  OwnedMaterials owns;
  const Vec3* other_acceleration;
  ImplicitViscosityArrays a;
  Real dt;
  UPF_HD void operator()(std::uint32_t i) const {
    const bool solved = f.type[i] == ParticleType::Liquid && owns(f.material[i]);
    a.solution[i] = solved ? f.v[i] + (other_acceleration[i] + a.warm[i]) * dt : f.v[i];
    a.search[i] = Vec3{};
  }
};

// The block-Jacobi preconditioner D_i^-1, D_i = m_i I + dt sum c (-grad W) x^T, and the residual
// r_i = m_i v*_i - (m_i u_i - dt F_i(u)) with the walls' and bodies' velocities, then z = D^-1 r.
// F_i(u) goes into `product` (free until the first iteration): when the warm start is already
// within the tolerance, it is the force, and no second pass over the neighbours is needed.
struct ViscosityResidualStage {
  FluidView f;
  const Real* density;
  FluidGradients gradient;
  const Vec3* other_acceleration;
  ImplicitViscosityArrays a;
  Real dt;
  UPF_HD void operator()(std::uint32_t i) const {
    Vec3 diag, off;
    const Vec3 force = implicit_viscosity_detail::viscous_force(f, density, gradient, a.solution,
                                                                true, i, &diag, &off);
    const Real m = f.mass[i];
    // D = m I - dt * (the derivative of F_i by u_i).
    const Real dxx = m - dt * diag.x, dyy = m - dt * diag.y, dzz = m - dt * diag.z;
    const Real dxy = -dt * off.x, dxz = -dt * off.y, dyz = -dt * off.z;
    const Real cxx = dyy * dzz - dyz * dyz, cxy = dxz * dyz - dxy * dzz,
               cxz = dxy * dyz - dxz * dyy;
    const Real inv_det = Real(1) / (dxx * cxx + dxy * cxy + dxz * cxz);
    const Vec3 inv_d{cxx * inv_det, (dxx * dzz - dxz * dxz) * inv_det,
                     (dxx * dyy - dxy * dxy) * inv_det};
    const Vec3 inv_o{cxy * inv_det, cxz * inv_det, (dxy * dxz - dxx * dyz) * inv_det};
    a.inverse_diagonal[i] = inv_d;
    a.inverse_off_diagonal[i] = inv_o;
    const Vec3 b = (f.v[i] + other_acceleration[i] * dt) * m;
    const Vec3 r = b - (a.solution[i] * m - force * dt);
    a.residual[i] = r;
    a.preconditioned[i] = implicit_viscosity_detail::apply_inverse(inv_d, inv_o, r);
    a.product[i] = force;
  }
};

// q = A p = m p - dt F(p) with the boundary at rest (the known velocities are in b).
struct ViscosityProductStage {
  FluidView f;
  const Real* density;
  FluidGradients gradient;
  ImplicitViscosityArrays a;
  Real dt;
  UPF_HD void operator()(std::uint32_t i) const {
    const Vec3 force =
        implicit_viscosity_detail::viscous_force(f, density, gradient, a.search, false, i);
    a.product[i] = a.search[i] * f.mass[i] - force * dt;
  }
};

// u += alpha p, r -= alpha q, z = D^-1 r.
struct ViscosityUpdateStage {
  ImplicitViscosityArrays a;
  Real alpha;
  UPF_HD void operator()(std::uint32_t i) const {
    a.solution[i] += a.search[i] * alpha;
    a.residual[i] -= a.product[i] * alpha;
    a.preconditioned[i] = implicit_viscosity_detail::apply_inverse(
        a.inverse_diagonal[i], a.inverse_off_diagonal[i], a.residual[i]);
  }
};

// p = z + beta p.
struct ViscositySearchStage {
  ImplicitViscosityArrays a;
  Real beta;
  UPF_HD void operator()(std::uint32_t i) const {
    a.search[i] = a.preconditioned[i] + a.search[i] * beta;
  }
};

// a_visc = F_i(u) / m_i at the solved velocities, kept for the next warm start and added to
// a_other; with `force_known`, F_i(u) is the residual stage's (no iteration moved u).
struct ViscousAccelerationStage {
  FluidView f;
  const Real* density;
  FluidGradients gradient;
  ImplicitViscosityArrays a;
  Vec3* other_acceleration;
  bool force_known;
  UPF_HD void operator()(std::uint32_t i) const {
    const Vec3 force = force_known ? a.product[i]
                                   : implicit_viscosity_detail::viscous_force(f, density, gradient,
                                                                              a.solution, true, i);
    const Vec3 acc = force / f.mass[i];
    a.warm[i] = acc;
    other_acceleration[i] += acc;
  }
};

// The dot products, in double per particle, summed exactly.
struct DotOf {
  const Vec3* a;
  const Vec3* b;
  UPF_HD double operator()(std::uint32_t i) const {
    return double(a[i].x) * double(b[i].x) + double(a[i].y) * double(b[i].y) +
           double(a[i].z) * double(b[i].z);
  }
};

// b^T D^-1 b with b = m v*: the norm the residual is measured against.
struct RightHandSideNorm {
  FluidView f;
  const Vec3* other_acceleration;
  ImplicitViscosityArrays a;
  Real dt;
  UPF_HD double operator()(std::uint32_t i) const {
    const Vec3 b = (f.v[i] + other_acceleration[i] * dt) * f.mass[i];
    const Vec3 z = implicit_viscosity_detail::apply_inverse(a.inverse_diagonal[i],
                                                            a.inverse_off_diagonal[i], b);
    return double(b.x) * double(z.x) + double(b.y) * double(z.y) + double(b.z) * double(z.z);
  }
};

// What a solve that did not converge says (ConvergenceError): the residual, the tolerance, the
// cap, and what to change.
inline std::string implicit_viscosity_failure(const ImplicitViscosityStats& stats,
                                              const ImplicitViscositySettings& s) {
  std::ostringstream out;
  out << "implicit viscosity did not converge: relative residual " << stats.residual
      << " above viscosity_tolerance " << s.tolerance << " after " << stats.iterations
      << " iterations (viscosity_max_iterations " << s.max_iterations
      << "); raise the liquid's viscosity_max_iterations or lower the time step (cfl)";
  return out.str();
}

// The whole solve on any executor; adds the viscous acceleration to other_acceleration of the
// owned particles. `all` spans every particle (the known velocities are set there).
template <class Executor>
ImplicitViscosityStats solve_implicit_viscosity(const Executor& exec, ParticleRange owned,
                                                std::size_t all, const FluidView& f,
                                                OwnedMaterials owns, const Real* density,
                                                FluidGradients gradient, Vec3* other_acceleration,
                                                const ImplicitViscosityArrays& a,
                                                const ImplicitViscositySettings& s, Real dt) {
  ImplicitViscosityStats stats;
  exec.run(all_particles(all), ViscosityStartStage{f, owns, other_acceleration, a, dt});
  exec.run(owned, ViscosityResidualStage{f, density, gradient, other_acceleration, a, dt});
  const double b_norm =
      scaled_fixed_point_sum(exec, owned, RightHandSideNorm{f, other_acceleration, a, dt});
  exec.run(owned, ViscositySearchStage{a, Real(0)});
  double rz = scaled_fixed_point_sum(exec, owned, DotOf{a.residual, a.preconditioned});
  const double target = s.tolerance * s.tolerance * b_norm;
  while (!(rz <= target)) {
    if (stats.iterations >= s.max_iterations) {
      stats.converged = false;
      break;
    }
    exec.run(owned, ViscosityProductStage{f, density, gradient, a, dt});
    const double pq = scaled_fixed_point_sum(exec, owned, DotOf{a.search, a.product});
    if (!(pq > 0)) {  // p = 0 (nothing left to solve), or a matrix that is not positive
      stats.converged = rz <= target;
      break;
    }
    exec.run(owned, ViscosityUpdateStage{a, Real(rz / pq)});
    const double rz_next = scaled_fixed_point_sum(exec, owned, DotOf{a.residual, a.preconditioned});
    exec.run(owned, ViscositySearchStage{a, Real(rz_next / rz)});
    rz = rz_next;
    ++stats.iterations;
  }
  stats.residual = b_norm > 0 ? std::sqrt(rz / b_norm) : std::sqrt(rz);
  exec.run(owned, ViscousAccelerationStage{f, density, gradient, a, other_acceleration,
                                           stats.iterations == 0});
  return stats;
}

}  // namespace upf
