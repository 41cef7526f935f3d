// The constants of the shared viscosity's Laplacian (fluid_forces.h, implicit_viscosity.h), from
// the kernel and the particle spacing:
//   nu lap(v)_i = F nu sum_j V_j (v_ij . x_ij) / (|x_ij|^2 + 0.01 H^2) grad W_ij.
// Monaghan 2005 (Rep. Prog. Phys. 68, eq. 6.1 form) takes F = 2 (d + 2) = 10, the value that makes
// the sum exact in the continuum limit. With the cubic spline at H = 2 s a particle has only 26
// neighbours, and on the initial lattice that sum gives 0.698 of the Laplacian: a liquid with
// F = 10 is 30 % less viscous than its nu says (a shear wave between two walls decayed at 0.68 of
// its analytic rate, docs/viscosity.md). The implicit viscosity, whose nu is a physical one
// (honey), takes F calibrated on the lattice, as Akinci's gamma is for surface tension:
// F = 1 / (the sum with F = 1 for v = (y^2 / 2, 0, 0), whose Laplacian is (1, 0, 0)), which goes
// to 2 (d + 2) as H / s grows. The explicit viscosity keeps the paper's 10: its default nu is a
// numerical damping every validated scene was tuned with (docs/viscosity.md says what changing it
// did).
//
// The explicit viscosity's stable step follows from the operator's largest decay rate, which on
// the lattice is nu * stiffness with stiffness the largest eigenvalue of -F sum (...) for a plane
// wave (the longitudinal one of wave number pi / s, found on the lattice): symplectic Euler needs
// dt < 2 / (nu stiffness); the limit taken is half of it, 0.070 s^2 / nu with F = 10. (Morris et
// al. 1997's 0.125 h^2 / nu has h = H / 2; with H it was 7 times this one, and a shear wave at
// nu = 0.1 m^2/s blew up at a step of 2e-4 s, under it.)
#pragma once

namespace upf {

struct ViscosityOperator {
  double laplacian_factor = 10;  // F
  double stiffness = 0;          // [1/m^2] the largest decay rate per unit nu
};

// F (calibrated, or the paper's 10) and the stiffness of the cubic spline of support radius H on
// the cubic lattice of spacing s.
ViscosityOperator viscosity_operator(double spacing, double support_radius, bool calibrated);

}  // namespace upf
