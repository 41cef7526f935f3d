// The continuum surface force (solvers/fluid/continuum_surface_force.h; Brackbill et al. 1992),
// the second surface tension model: a resting drop's pressure is Laplace's 2 sigma / R (Laplace
// 1806), which Akinci et al. 2013's pair forces miss by 2.5 to 3.2 times (docs/surface-tension.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "drop_scenes.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Liquid {
  std::vector<Vec3> x;
  std::vector<Real> pressure;
};

Liquid liquid_of(const World& world) {
  const Particles& p = world.particles();
  const std::vector<Real>& pressure = *p.find_scalar("pressure");
  Liquid l;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Liquid) {
      l.x.push_back(p.position[i]);
      l.pressure.push_back(pressure[i]);
    }
  return l;
}

Vec3 centroid(const std::vector<Vec3>& x) {
  Vec3 c{0, 0, 0};
  for (const Vec3& xi : x) c += xi;
  return c * (Real(1) / Real(x.size()));
}

// The radius of the ball of the particles' volume, n s^3.
double volume_radius(std::size_t n, double spacing) {
  return spacing * std::cbrt(3.0 * double(n) / (4 * kPi));
}

// A drop of R = 8 spacings of 2.5 mm (2,176 particles), sigma 0.0728 N/m, nu 1e-4 m^2/s, no
// gravity, each incompressible solver at the step it picks: the mean pressure within R / 2 of the
// centre, every fifth step from 0.2 to 0.4 s, is Laplace's jump 2 sigma / R within 10 % (a flat
// face has no curvature, so the liquid outside reads 0), and every particle stays within 1.3 R.
class ContinuumSurfaceForceDrop : public ::testing::TestWithParam<const char*> {};

TEST_P(ContinuumSurfaceForceDrop, RestingDropHasLaplacesPressure) {
  DropScene d;
  d.solver = GetParam();
  d.radius = 8 * d.spacing;
  d.viscosity = 1e-4;
  d.model = "csf";
  TestWorld t(drop_scene(d), 2);
  const double radius = volume_radius(liquid_of(*t.world).x.size(), d.spacing);
  double sum = 0, farthest = 0;
  int samples = 0, step = 0;
  while (t.world->time() < 0.4) {
    t.world->step(t.world->next_time_step_until(0.4));
    if (t.world->time() < 0.2 || ++step % 5) continue;
    const Liquid l = liquid_of(*t.world);
    const Vec3 c = centroid(l.x);
    double inside = 0;
    int count = 0;
    for (std::size_t i = 0; i < l.x.size(); ++i) {
      const double r = norm(l.x[i] - c);
      farthest = std::max(farthest, r);
      if (r < radius / 2) inside += l.pressure[i], ++count;
    }
    sum += inside / count;
    ++samples;
  }
  const double laplace = 2 * d.sigma / radius;
  const double measured = sum / samples;
  std::printf(
      "%s, resting drop: %.3f Pa inside against Laplace's %.3f Pa (ratio %.3f, %d samples); "
      "farthest particle %.2f R\n",
      d.solver.c_str(), measured, laplace, measured / laplace, samples, farthest / radius);
  record_validation("pressure inside a resting drop of 8 spacings / 2 sigma / R, csf, " + d.solver,
                    "Laplace 1806", "1", "within 10 %", measured / laplace);
  EXPECT_NEAR(measured / laplace, 1.0, 0.10);
  EXPECT_LT(farthest, 1.3 * radius);
}

INSTANTIATE_TEST_SUITE_P(IncompressibleSolvers, ContinuumSurfaceForceDrop,
                         ::testing::Values("pcisph", "dfsph", "iisph"));

// Rayleigh 1879: a drop's n = 2 mode oscillates at omega^2 = 8 sigma / (rho0 R^3), damped at
// 5 nu / R^2 (Lamb 1932, art. 355), so that its extremes come every pi / sqrt(omega^2 - (5 nu /
// R^2)^2). A drop of R = 12 spacings of 2.5 mm (7,208 particles), sigma 0.0728 N/m, nu 1e-4 m^2/s,
// no gravity, started by the mode's potential flow v = a (-x, -y, 2z) at 10 % of R: the time from
// the first maximum of its deformation <z^2> - (<x^2> + <y^2>) / 2 to the second is that period
// within 5 % (1.36 s). PCISPH at steps of at most 0.5 ms; at the 0.85 ms it picks itself the
// period comes out 7 % short, and DFSPH's 12 % short (docs/surface-tension.md).
TEST(ContinuumSurfaceForce, DropOscillatesAtRayleighsPeriod) {
  DropScene d;
  d.radius = 12 * d.spacing;
  d.viscosity = 1e-4;
  d.model = "csf";
  nlohmann::json doc = drop_scene(d);
  doc["time"]["dt_max"] = 0.0005;
  TestWorld t(doc, 2);
  Particles& p = t.world->particles();
  const std::vector<Vec3> start = liquid_of(*t.world).x;
  const double radius = volume_radius(start.size(), d.spacing);
  const double omega = std::sqrt(8 * d.sigma / (1000 * radius * radius * radius));
  const double damping = 5 * d.viscosity / (radius * radius);
  const double period = 2 * kPi / std::sqrt(omega * omega - damping * damping);
  const Vec3 c0 = centroid(start);
  const Real rate = Real(0.1 * omega / 2);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Liquid) {
      const Vec3 x = p.position[i] - c0;
      p.velocity[i] = Vec3{-x.x, -x.y, 2 * x.z} * rate;
    }
  std::vector<double> time, shape;
  const double end = 1.4 * period;
  while (t.world->time() < end) {
    t.world->step(t.world->next_time_step_until(end));
    const std::vector<Vec3> x = liquid_of(*t.world).x;
    const Vec3 c = centroid(x);
    double zz = 0, xy = 0;
    for (const Vec3& xi : x) {
      const Vec3 r = xi - c;
      zz += double(r.z) * r.z;
      xy += 0.5 * (double(r.x) * r.x + double(r.y) * r.y);
    }
    time.push_back(t.world->time());
    shape.push_back((zz - xy) / double(x.size()));
  }
  // The extreme of `sign` times the shape between times a and b.
  auto extreme = [&](double a, double b, double sign) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < time.size(); ++k)
      if (time[k] >= a && time[k] < b && (best == 0 || sign * shape[k] > sign * shape[best]))
        best = k;
    return time[best];
  };
  const double first = extreme(0, 0.5 * period, 1);
  const double trough = extreme(first + 0.2 * period, first + 0.8 * period, -1);
  const double second = extreme(trough + 0.2 * period, trough + 0.8 * period, 1);
  std::printf(
      "n = 2 drop: maxima at %.3f and %.3f s (minimum at %.3f s), period %.4f s against "
      "Rayleigh-Lamb %.4f s (ratio %.3f)\n",
      first, second, trough, second - first, period, (second - first) / period);
  record_validation("n = 2 period of a drop of 12 spacings / Rayleigh's (Lamb-damped), csf",
                    "Rayleigh 1879, Lamb 1932", "1", "within 5 %", (second - first) / period);
  EXPECT_NEAR((second - first) / period, 1.0, 0.05);
}

}  // namespace
}  // namespace upf::testing
