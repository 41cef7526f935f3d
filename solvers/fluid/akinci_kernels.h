// The two kernels of Akinci, Akinci & Teschner 2013 ("Versatile surface tension and adhesion for
// SPH fluids", ACM TOG 32(6) 182), with H the support radius:
//   cohesion (eq. 2)  C(r) = 32 / (pi H^9) * { (H - r)^3 r^3                H/2 < r <= H
//                                              2 (H - r)^3 r^3 - H^6 / 64   0 < r <= H/2 }
//   adhesion (eq. 7)  A(r) = 0.007 / H^3.25 * (-4 r^2 / H + 6 r - 2 H)^(1/4)   H/2 < r <= H
// and 0 elsewhere. C is attractive beyond H/2 and repulsive inside it; A only attracts.
//
// Surface tension of the cohesion force. The pair force F = gamma m_i m_j C(r) is the derivative
// of a pair potential, so a liquid of uniform density rho0 up to a flat face has the surface
// tension of Kirkwood & Buff 1949 (J. Chem. Phys. 17, 338) with a step density profile,
//   sigma = (pi / 8) n^2 int_0^H r^4 phi'(r) dr = 4 gamma rho0^2 H^2 I4,
//   I4 = int_0^1 u^4 c(u) du = 21/28160, c(u) = C(u H) pi H^3 / 32,
// the continuum limit of the lattice sum that turns a coefficient in N/m into Akinci's gamma
// (surface_tension_models.h; the sum gives 0.76 of it at H = 2 s).
#pragma once

#include <cmath>

#include "framework/core/real.h"

namespace upf {

class AkinciCohesionKernel {
 public:
  AkinciCohesionKernel() = default;
  UPF_HD explicit AkinciCohesionKernel(Real support_radius)
      : h_(support_radius),
        h6_over_64_(pow6(support_radius) / Real(64)),
        k_(Real(32) /
           (kPi * pow6(support_radius) * support_radius * support_radius * support_radius)) {}

  UPF_HD Real value(Real r) const {
    if (r >= h_ || r <= Real(0)) return 0;
    const Real a = (h_ - r) * r;
    const Real cube = a * a * a;
    if (Real(2) * r > h_) return k_ * cube;
    return k_ * (Real(2) * cube - h6_over_64_);
  }

 private:
  UPF_HD static Real pow6(Real x) {
    const Real x3 = x * x * x;
    return x3 * x3;
  }
  static constexpr Real kPi = Real(3.14159265358979323846);
  Real h_ = 0, h6_over_64_ = 0, k_ = 0;
};

class AkinciAdhesionKernel {
 public:
  AkinciAdhesionKernel() = default;
  // 0.007 / H^3.25 = 0.007 / (H^3 H^(1/4)).
  UPF_HD explicit AkinciAdhesionKernel(Real support_radius)
      : h_(support_radius),
        k_(Real(0.007) / (support_radius * support_radius * support_radius *
                          std::sqrt(std::sqrt(support_radius)))) {}

  UPF_HD Real value(Real r) const {
    if (r >= h_ || Real(2) * r <= h_) return 0;
    const Real inner = Real(-4) * r * r / h_ + Real(6) * r - Real(2) * h_;
    return inner > 0 ? k_ * std::sqrt(std::sqrt(inner)) : Real(0);
  }

 private:
  Real h_ = 0, k_ = 0;
};

}  // namespace upf
