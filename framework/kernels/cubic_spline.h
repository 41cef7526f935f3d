// Cubic spline kernel (Monaghan 1992, "Smoothed particle hydrodynamics", Annu. Rev. Astron.
// Astrophys. 30), written with the support radius H (= 2h) as in SPlisHSPlasH:
//   q = r / H,  W = k (6q^3 - 6q^2 + 1) for q <= 1/2,  W = 2k (1 - q)^3 for q <= 1,  k = 8/(pi
//   H^3).
// The default kernel of every fluid solver.
#pragma once

#include "framework/core/vec3.h"

namespace upf {

class CubicSplineKernel {
 public:
  CubicSplineKernel() = default;
  UPF_HD explicit CubicSplineKernel(Real support_radius)
      : h_(support_radius),
        inv_h_(Real(1) / support_radius),
        k_(Real(8) / (kPi * support_radius * support_radius * support_radius)),
        l_(Real(48) / (kPi * support_radius * support_radius * support_radius)) {}

  UPF_HD Real support_radius() const { return h_; }

  // Support tests compare r with H, not q with 1: r * (1/H) can round below 1 at r = H.
  UPF_HD Real value(Real r) const {
    if (r >= h_) return 0;
    const Real q = r * inv_h_;
    if (q <= Real(0.5)) return k_ * (Real(6) * q * q * q - Real(6) * q * q + Real(1));
    const Real a = Real(1) - q;
    return k_ * Real(2) * a * a * a;
  }
  UPF_HD Real value(const Vec3& r) const { return value(norm(r)); }

  // The same value, bit for bit, with both pieces evaluated and selected: a loop over pairs then
  // vectorises (solvers/fluid/kernel_sum.h) where value()'s branches, mispredicted at random
  // distances, do not.
  UPF_HD Real value_without_branches(Real r) const {
    const Real q = r * inv_h_;
    const Real a = Real(1) - q;
    const Real inner = k_ * (Real(6) * q * q * q - Real(6) * q * q + Real(1));
    const Real outer = k_ * Real(2) * a * a * a;
    const Real w = q <= Real(0.5) ? inner : outer;
    return r >= h_ ? Real(0) : w;
  }

  // Value and gradient together (one square root), for loops that need both.
  UPF_HD Real value_and_gradient(const Vec3& r, Vec3& gradient) const {
    const Real rl = norm(r);
    gradient = Vec3{};
    if (rl >= h_) return 0;
    const Real q = rl * inv_h_;
    if (q <= Real(0.5)) {
      if (rl > Real(1e-9) * h_) gradient = r * (l_ * q * (Real(3) * q - Real(2)) / (rl * h_));
      return k_ * (Real(6) * q * q * q - Real(6) * q * q + Real(1));
    }
    const Real a = Real(1) - q;
    gradient = r * (-l_ * a * a / (rl * h_));
    return k_ * Real(2) * a * a * a;
  }

  // Gradient with respect to the first particle's position, r = x_i - x_j.
  UPF_HD Vec3 gradient(const Vec3& r) const {
    const Real rl = norm(r);
    if (rl >= h_ || rl <= Real(1e-9) * h_) return {};
    const Real q = rl * inv_h_;
    const Vec3 dir = r / (rl * h_);  // grad q = r / (|r| H)
    if (q <= Real(0.5)) return dir * (l_ * q * (Real(3) * q - Real(2)));
    const Real a = Real(1) - q;
    return dir * (-l_ * a * a);
  }

 private:
  static constexpr Real kPi = Real(3.14159265358979323846);
  Real h_ = 0, inv_h_ = 0, k_ = 0, l_ = 0;
};

}  // namespace upf
