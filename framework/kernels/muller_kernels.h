// The kernels of Müller, Charypar & Gross 2003, "Particle-based fluid simulation for interactive
// applications" (SCA 2003), with support radius H:
//   poly6       W = 315 / (64 pi H^9) (H^2 - r^2)^3           (density)
//   spiky       grad W = -45 / (pi H^6) (H - r)^2 r/|r|        (pressure: no vanishing gradient)
//   viscosity   lap W = 45 / (pi H^6) (H - r)                  (viscosity: positive Laplacian)
#pragma once

#include "framework/core/vec3.h"

namespace upf {

class MullerKernels {
 public:
  MullerKernels() = default;
  UPF_HD explicit MullerKernels(Real support_radius) : h_(support_radius) {
    const Real h3 = h_ * h_ * h_;
    const Real h6 = h3 * h3;
    poly6_ = Real(315) / (Real(64) * kPi * h6 * h3);
    spiky_ = Real(45) / (kPi * h6);
    spiky_value_ = Real(15) / (kPi * h6);
    viscosity_ = Real(45) / (kPi * h6);
    viscosity_value_ = Real(15) / (Real(2) * kPi * h3);
  }

  UPF_HD Real support_radius() const { return h_; }

  UPF_HD Real poly6(Real r) const {
    if (r > h_) return 0;
    const Real d = h_ * h_ - r * r;
    return poly6_ * d * d * d;
  }
  UPF_HD Vec3 poly6_gradient(const Vec3& r) const {
    const Real r2 = squared_norm(r);
    if (r2 > h_ * h_) return {};
    const Real d = h_ * h_ - r2;
    return r * (Real(-6) * poly6_ * d * d);
  }

  UPF_HD Real spiky(Real r) const {
    if (r > h_) return 0;
    const Real d = h_ - r;
    return spiky_value_ * d * d * d;
  }
  UPF_HD Vec3 spiky_gradient(const Vec3& r) const {
    const Real rl = norm(r);
    if (rl > h_ || rl <= Real(1e-9) * h_) return {};
    const Real d = h_ - rl;
    return r * (-spiky_ * d * d / rl);
  }

  // The viscosity kernel W(r) = 15/(2 pi H^3) (-q^3/2 + q^2 + 1/(2q) - 1), q = r/H, and its
  // Laplacian, which is what the SPH viscosity force uses.
  UPF_HD Real viscosity(Real r) const {
    if (r > h_ || r <= Real(0)) return 0;
    const Real q = r / h_;
    // -q^3/2 + q^2 + 1/(2q) - 1 = (1-q)^3 (1+q) / (2q): the factored form keeps its digits near H.
    const Real a = Real(1) - q;
    return viscosity_value_ * a * a * a * (Real(1) + q) / (Real(2) * q);
  }
  UPF_HD Real viscosity_laplacian(Real r) const {
    if (r > h_) return 0;
    return viscosity_ * (h_ - r);
  }

 private:
  static constexpr Real kPi = Real(3.14159265358979323846);
  Real h_ = 0, poly6_ = 0, spiky_ = 0, spiky_value_ = 0, viscosity_ = 0, viscosity_value_ = 0;
};

}  // namespace upf
