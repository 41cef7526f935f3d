#include "solvers/fluid/viscosity_operator.h"

#include <cmath>

#include "framework/kernels/cubic_spline.h"

namespace upf {

ViscosityOperator viscosity_operator(double spacing, double support_radius, bool calibrated) {
  const CubicSplineKernel kernel{Real(support_radius)};
  const double h2 = support_radius * support_radius;
  const double volume = spacing * spacing * spacing;
  constexpr double kPi = 3.14159265358979323846;
  const int reach = int(std::ceil(support_radius / spacing));
  double quadratic = 0;     // the sum with F = 1 for v = (y^2 / 2, 0, 0), at the origin
  double longitudinal = 0;  // -(the sum with F = 1) for v = (cos(pi x / s), 0, 0), at the origin
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = -reach; k <= reach; ++k) {
        if (i == 0 && j == 0 && k == 0) continue;
        const double x = i * spacing, y = j * spacing, z = k * spacing;
        const double r2 = x * x + y * y + z * z;
        if (r2 >= h2) continue;
        // x_ij = x_i - x_j = -(x, y, z) with particle i at the origin.
        const Vec3 gradient = kernel.gradient(Vec3{Real(-x), Real(-y), Real(-z)});
        const double weight = volume / (r2 + 0.01 * h2);
        quadratic += weight * (-0.5 * y * y) * (-x) * double(gradient.x);
        longitudinal -= weight * (1 - std::cos(kPi * i)) * (-x) * double(gradient.x);
      }
  ViscosityOperator op;
  op.laplacian_factor = calibrated ? 1 / quadratic : 10;
  op.stiffness = op.laplacian_factor * longitudinal;
  return op;
}

}  // namespace upf
