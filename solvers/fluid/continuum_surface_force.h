// The continuum surface force, the second surface tension model of the shared fluid pieces
// ("csf"; docs/surface-tension.md):
//   force (Brackbill, Kothe & Zemach 1992, "A continuum method for modeling surface tension",
//   J. Comput. Phys. 100)   a_i = sigma kappa_i (grad c_i . n_i) n_i / (c0 rho0),
//   colour gradient         grad c_i = sum_j V_j grad W_ij = Akinci's normal / H (fluid_forces.h),
//   normal                  n_i = the kernel average of the surface neighbours' outward unit
//                           normals -grad c_j / |grad c_j| (SmoothedNormalStage),
//   curvature               kappa = div_s n = G_11 + G_22, where G is the least-squares gradient
//                           of the smoothed normals in i's tangent plane, n_j - n_i = G (x_j - x_i)
//                           + b over the surface neighbours (FittedCurvatureStage), then averaged
//                           with W over the fitted neighbours,
//   c0                      what the colour gradient of a particle face sums to per unit area
//                           (csf_face_gradient_per_area; 0.51 at H = 2 s), so that the force
//                           summed over a face is sigma kappa times its area: Laplace's jump.
// A surface particle is one with |H grad c| > kCsfSurfaceGradient (0 inside the liquid, 1.02 on a
// flat face of the lattice). Why each piece (measured on free drops, docs/surface-tension.md):
//   - the divergence of the colour gradient's own normals (Morris 2000) reads the lattice's
//     staircase (4 times 2 / R on a ball of 8 spacings); smoothed normals carry the surface's shape
//     from two support radii, so their gradient reads it within a few percent;
//   - a quadric fitted to the positions within one support radius scattered by more than its
//     value and let a drop of 12 spacings fall apart; the normals' gradient needs one derivative,
//     not two;
//   - the force acts along the smoothed normal, not along grad c_i: grad c_i also points
//     tangentially toward denser parts of the surface, and that part made surface particles
//     cluster until a drop fell apart.
// Not pairwise, so it keeps momentum only as far as a closed surface's forces cancel. Adhesion
// stays Akinci's (surface_forces.h). C++17 and UPF_HD: the device pipeline runs the same functions.
#pragma once

#include <cmath>
#include <cstdint>

#include "solvers/fluid/fluid_view.h"

namespace upf {

inline constexpr Real kCsfSurfaceGradient = Real(0.3);
// The fewest surface neighbours the normals' gradient (2 x 2 and an offset) is fitted to.
inline constexpr std::uint32_t kCsfFewestFitted = 4;

namespace csf_detail {

// The outward unit normal from Akinci's inward normal n = H grad c (zero inside).
UPF_HD inline Vec3 outward(const Vec3& n) {
  const Real size = norm(n);
  return size > Real(0) ? n * (Real(-1) / size) : Vec3{};
}

UPF_HD inline bool on_surface(const Vec3& n) {
  return squared_norm(n) > kCsfSurfaceGradient * kCsfSurfaceGradient;
}

// Solves the symmetric positive definite 3 x 3 system m x = b (both right-hand sides in b) by
// Cholesky; false where m is not positive definite.
UPF_HD inline bool solve_symmetric3(const Real (&m)[3][3], Real (&b)[2][3]) {
  Real l[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= i; ++j) {
      Real sum = m[i][j];
      for (int k = 0; k < j; ++k) sum -= l[i][k] * l[j][k];
      if (i == j) {
        if (!(sum > Real(1e-6))) return false;  // offsets in units of H: entries of order 1
        l[i][i] = std::sqrt(sum);
      } else {
        l[i][j] = sum / l[j][j];
      }
    }
  for (auto& x : b) {
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < i; ++k) x[i] -= l[i][k] * x[k];
      x[i] /= l[i][i];
    }
    for (int i = 2; i >= 0; --i) {
      for (int k = i + 1; k < 3; ++k) x[i] -= l[k][i] * x[k];
      x[i] /= l[i][i];
    }
  }
  return true;
}

}  // namespace csf_detail

// The kernel average of the surface neighbours' outward unit normals at surface particle i (unit
// length), zero off the surface.
UPF_HD inline Vec3 smoothed_surface_normal(const FluidView& f, std::uint32_t i) {
  const Vec3* normal = f.surface.normal;
  if (!csf_detail::on_surface(normal[i])) return {};
  Vec3 sum = csf_detail::outward(normal[i]) * f.kernel.value(Real(0));
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    if (j == i || !csf_detail::on_surface(normal[j])) continue;
    sum += csf_detail::outward(normal[j]) * f.kernel.value(norm(f.x[i] - f.x[j]));
  }
  return sum * (Real(1) / norm(sum));
}

struct SmoothedNormalStage {
  FluidView f;
  Vec3* smoothed;
  UPF_HD void operator()(std::uint32_t i) const { smoothed[i] = smoothed_surface_normal(f, i); }
};

// The curvature [1/m] at surface particle i, and 1 where it was fitted (at least kCsfFewestFitted
// surface neighbours, a well-posed fit), else 0 and 0.
struct FittedCurvature {
  Real curvature = 0;
  Real weight = 0;
};

UPF_HD inline FittedCurvature fit_surface_curvature(const FluidView& f, const Vec3* smoothed,
                                                    std::uint32_t i) {
  const Vec3 e3 = smoothed[i];
  if (squared_norm(e3) == Real(0)) return {};
  // A tangent frame: the axis least along e3 crossed with it.
  const Vec3 axis = std::fabs(e3.x) < Real(0.9) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 e1 = cross(e3, axis);
  e1 = e1 * (Real(1) / norm(e1));
  const Vec3 e2 = cross(e3, e1);
  // Offsets in units of H, so that the normal equations' entries are of order 1.
  const Real inv_h = Real(1) / f.kernel.support_radius();
  Real m[3][3] = {};
  Real rhs[2][3] = {};  // the normals' change along e1 and along e2
  m[2][2] = 1;          // the particle itself, at the frame's origin
  std::uint32_t fitted = 0;
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    if (j == i || squared_norm(smoothed[j]) == Real(0)) continue;
    const Vec3 d = (f.x[j] - f.x[i]) * inv_h;
    const Vec3 dn = smoothed[j] - e3;
    const Real phi[3] = {dot(d, e1), dot(d, e2), Real(1)};
    const Real change[2] = {dot(dn, e1), dot(dn, e2)};
    for (int a = 0; a < 3; ++a) {
      rhs[0][a] += phi[a] * change[0];
      rhs[1][a] += phi[a] * change[1];
      for (int c = 0; c < 3; ++c) m[a][c] += phi[a] * phi[c];
    }
    ++fitted;
  }
  if (fitted < kCsfFewestFitted || !csf_detail::solve_symmetric3(m, rhs)) return {};
  // G_11 + G_22: d(n . e1)/du + d(n . e2)/dv.
  return {(rhs[0][0] + rhs[1][1]) * inv_h, Real(1)};
}

struct FittedCurvatureStage {
  FluidView f;
  const Vec3* smoothed;
  Real* curvature;
  Real* weight;
  UPF_HD void operator()(std::uint32_t i) const {
    const FittedCurvature k = fit_surface_curvature(f, smoothed, i);
    curvature[i] = k.curvature;
    weight[i] = k.weight;
  }
};

// The continuum surface force on liquid particle i, as an acceleration: f.surface.cohesion holds
// sigma / (c0 rho0) per material.
UPF_HD inline Vec3 csf_tension_acceleration(const FluidView& f, std::uint32_t i) {
  const SurfaceForceView& s = f.surface;
  if (s.curvature_weight[i] <= Real(0)) return {};
  const Real coefficient = s.cohesion[f.material[i]];
  if (coefficient <= Real(0)) return {};
  const Real w0 = f.kernel.value(Real(0));
  Real curvature = w0 * s.curvature[i], weights = w0;
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    if (j == i || s.curvature_weight[j] <= Real(0)) continue;
    const Real w = f.kernel.value(norm(f.x[i] - f.x[j]));
    curvature += w * s.curvature[j];
    weights += w;
  }
  const Vec3 n = s.smoothed_normal[i];
  // grad c . n with grad c = normal / H: negative, grad c points into the liquid.
  const Real along = dot(s.normal[i], n) / f.kernel.support_radius();
  return n * (coefficient * (curvature / weights) * along);
}

}  // namespace upf
