// The three kernels SPH evaluates (Müller, Charypar & Gross 2003, section 3.5), as two
// interchangeable sets chosen by the parameter `cubic_spline`:
//   MullerKernelSet   the paper's: poly6 for density, spiky gradient for pressure, the viscosity
//                     kernel's Laplacian for viscosity (framework/kernels/muller_kernels.h);
//   CubicKernelSet    the cubic spline every other fluid solver uses, for all three, with the
//                     Laplacian approximated after Brookshaw 1985 (Proc. ASA 6(2)):
//                       lap W_ij ~ -2 (x_ij . grad W_ij) / (|x_ij|^2 + 0.01 H^2)  >= 0,
//                     since the spline's own Laplacian changes sign and would accelerate
//                     approaching particles towards each other (the paper's reason for its
//                     viscosity kernel).
// Both take r = x_i - x_j. C++17 and UPF_HD: compiled by nvcc too.
#pragma once

#include "framework/kernels/cubic_spline.h"
#include "framework/kernels/muller_kernels.h"

namespace upf {

struct MullerKernelSet {
  MullerKernels w;
  UPF_HD Real density(const Vec3& r) const { return w.poly6(norm(r)); }
  UPF_HD Vec3 pressure_gradient(const Vec3& r) const { return w.spiky_gradient(r); }
  UPF_HD Real viscosity_laplacian(const Vec3& r) const { return w.viscosity_laplacian(norm(r)); }
};

struct CubicKernelSet {
  CubicSplineKernel w;
  UPF_HD Real density(const Vec3& r) const { return w.value(r); }
  UPF_HD Vec3 pressure_gradient(const Vec3& r) const { return w.gradient(r); }
  UPF_HD Real viscosity_laplacian(const Vec3& r) const {
    const Real h2 = w.support_radius() * w.support_radius();
    return Real(-2) * dot(r, w.gradient(r)) / (squared_norm(r) + Real(0.01) * h2);
  }
};

}  // namespace upf
