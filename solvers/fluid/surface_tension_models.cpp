#include "solvers/fluid/surface_tension_models.h"

#include <cmath>

#include "framework/kernels/cubic_spline.h"
#include "solvers/fluid/akinci_kernels.h"

namespace upf {

void register_surface_tension_models(Registry& registry) {
  registry.add_surface_tension_model(
      {"akinci2013",
       "pairwise cohesion and curvature minimisation, with adhesion to walls and bodies",
       "Akinci, Akinci & Teschner 2013, \"Versatile surface tension and adhesion for SPH fluids\", "
       "ACM TOG 32(6)"});
  registry.add_surface_tension_model(
      {"csf",
       "continuum surface force on the surface particles, with the curvature fitted to their "
       "smoothed normals; no adhesion yet (liquid beads on walls at about 157 degrees)",
       "Brackbill, Kothe & Zemach 1992, \"A continuum method for modeling surface tension\", "
       "J. Comput. Phys. 100",
       false});
}

SurfaceTensionModel surface_tension_model_named(const std::string& name) {
  // Empty: the liquid names none, and the first registered is the default.
  if (name.empty() || name == "akinci2013") return SurfaceTensionModel::Akinci2013;
  if (name == "csf") return SurfaceTensionModel::ContinuumSurfaceForce;
  return SurfaceTensionModel::None;
}

namespace {

// The layers of a flat face of the initial lattice within reach of one another: particles at
// depth (k + 1/2) s, k = 0 .. layers - 1, and lateral offsets up to `reach` spacings.
int reach_in_spacings(double spacing, double support) {
  return int(std::ceil(support / spacing)) + 1;
}

// int_r^H C(x) dx, Simpson's rule on 2000 intervals (C is a polynomial of degree 6 on each side
// of H/2, where an interval ends: the error is far below float precision).
double cohesion_integral(double r, double support) {
  if (r >= support) return 0;
  const AkinciCohesionKernel c{Real(support)};
  auto integrate = [&](double a, double b) {
    constexpr int kIntervals = 1000;
    const double step = (b - a) / kIntervals;
    double sum = double(c.value(Real(a))) + double(c.value(Real(b)));
    for (int i = 1; i < kIntervals; ++i)
      sum += (i % 2 ? 4.0 : 2.0) * double(c.value(Real(a + i * step)));
    return sum * step / 3;
  };
  const double half = 0.5 * support;
  return r < half ? integrate(r, half) + integrate(half, support) : integrate(r, support);
}

// Akinci: the work per area to split the lattice along a face between layers, with gamma = 1,
// is sigma's double: sigma = gamma rho0^2 s^4 / 2 * sum_{pairs across} int_r^H C.
double akinci_sigma_per_gamma(double rest_density, double spacing, double support) {
  const int reach = reach_in_spacings(spacing, support);
  double sum = 0;
  for (int up = 0; up < reach; ++up)
    for (int down = 0; down < reach; ++down)
      for (int a = -reach; a <= reach; ++a)
        for (int b = -reach; b <= reach; ++b) {
          const double dz = double(up + down + 1) * spacing;
          const double r = std::sqrt(double(a * a + b * b) * spacing * spacing + dz * dz);
          sum += cohesion_integral(r, support);
        }
  const double s2 = spacing * spacing;
  return rest_density * rest_density * s2 * s2 * sum / 2;
}

}  // namespace

double akinci_gamma_for_sigma(double sigma, double rest_density, double spacing, double support) {
  return sigma / akinci_sigma_per_gamma(rest_density, spacing, support);
}

double csf_face_gradient_per_area(double spacing, double support) {
  // Each layer's |sum_j V_j grad W_ij| over the half space of layers above it is missing, times
  // its volume per face area, s^3 / s^2.
  const CubicSplineKernel kernel{Real(support)};
  const int reach = reach_in_spacings(spacing, support);
  const double volume = spacing * spacing * spacing;
  double sum = 0;
  for (int depth = 0; depth < reach; ++depth) {
    double gradient = 0;  // along the face's normal; the lateral parts cancel
    for (int below = 0; below < 2 * reach + depth; ++below)
      for (int a = -reach; a <= reach; ++a)
        for (int b = -reach; b <= reach; ++b) {
          const Vec3 r{Real(a * spacing), Real(b * spacing), Real((below - depth) * spacing)};
          Vec3 g;
          (void)kernel.value_and_gradient(r, g);
          gradient += double(g.z) * volume;
        }
    sum += std::abs(gradient) * spacing;
  }
  return sum;
}

}  // namespace upf
