// Wendland C2 kernels of support radius r at distance d (Wendland 1995, "Piecewise polynomial,
// positive definite and compactly supported radial functions of minimal degree"; the
// normalisations of Dehnen & Aly 2012): each integrates to one over the plane (2D) or space
// (3D). Used where a smooth weight is wanted outside the solvers' own kernel: probes and the
// liquid surface's kernels.
#pragma once

namespace upf {

inline double wendland_2d(double d, double r) {
  constexpr double kPi = 3.14159265358979323846;
  const double q = d / r;
  if (q >= 1) return 0;
  const double a = 1 - q;
  return 7 / (kPi * r * r) * a * a * a * a * (1 + 4 * q);
}

inline double wendland_3d(double d, double r) {
  constexpr double kPi = 3.14159265358979323846;
  const double q = d / r;
  if (q >= 1) return 0;
  const double a = 1 - q;
  return 21 / (2 * kPi * r * r * r) * a * a * a * a * (1 + 4 * q);
}

}  // namespace upf
