// Fluid forces on a grain in a liquid, the grain side of unresolved SPH-DEM coupling:
//
//   drag (Di Felice 1994, "The voidage function for fluid-particle interaction systems",
//   Int. J. Multiphase Flow 20(1)):
//     F_d = 1/2 C_D rho_f pi r^2 eps^(2 - chi) |w| w,   w = u_f - v (relative velocity)
//     C_D = (0.63 + 4.8 / sqrt(Re))^2 (Dallavalle),    Re = rho_f 2r eps |w| / mu_f
//     chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2)
//   buoyancy: F_b = -rho_f V g (Archimedes with the hydrostatic pressure gradient).
//
// u_f, eps (the local voidage) and the fluid fraction phi come from SPH interpolation over the
// grain's liquid and granular neighbours; both forces are scaled by phi, so a grain half out of
// the water feels half of them. The opposite force goes to the liquid neighbours.
#pragma once

#include <cmath>

#include "framework/core/vec3.h"

namespace upf {

struct GrainFluidState {
  Vec3 fluid_velocity;       // u_f, m/s
  Real fluid_fraction = 0;   // phi in [0, 1]
  Real voidage = 1;          // eps in (0, 1]
  Real fluid_density = 0;    // rho_f, kg/m^3
  Real fluid_viscosity = 0;  // mu_f, Pa s
};

UPF_HD inline Vec3 di_felice_drag(const GrainFluidState& s, Real radius, const Vec3& v) {
  const Vec3 w = s.fluid_velocity - v;
  const Real speed = norm(w);
  if (speed <= 0 || s.fluid_fraction <= 0) return {};
  const Real re = s.fluid_density * Real(2) * radius * s.voidage * speed / s.fluid_viscosity;
  const Real cd_root = Real(0.63) + Real(4.8) / std::sqrt(re);
  const Real lg = Real(1.5) - std::log10(re);
  const Real chi = Real(3.7) - Real(0.65) * std::exp(-Real(0.5) * lg * lg);
  const Real area = Real(3.141592653589793) * radius * radius;
  return w * (Real(0.5) * cd_root * cd_root * s.fluid_density * area *
              std::pow(s.voidage, Real(2) - chi) * speed * s.fluid_fraction);
}

UPF_HD inline Vec3 grain_buoyancy(const GrainFluidState& s, Real volume, const Vec3& gravity) {
  return gravity * (-s.fluid_density * volume * s.fluid_fraction);
}

}  // namespace upf
