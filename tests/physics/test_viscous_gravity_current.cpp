// Columns of viscous liquid slumping on a no-slip floor (implicit viscosity, solvers/fluid/
// implicit_viscosity.h, with the no-slip walls of wall_velocity.h) against the axisymmetric viscous
// gravity current of constant volume V (Huppert 1982, "The propagation of two-dimensional and
// axisymmetric viscous gravity currents over a rigid horizontal surface", J. Fluid Mech. 121):
// once the current is thin and slow its front is at
//   r_N(t) = 0.894 (rho g V^3 t / (3 mu))^(1/8),  mu = rho nu,
// whatever the column's initial shape; so honey (nu = 0.1 m^2/s) spreads more slowly than a liquid
// five times thinner by 5^(1/8) = 1.22.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kSpacing = 0.01, kHalfWidth = 0.07, kHeight = 0.16, kTank = 0.7;
constexpr double kDensity = 1400, kG = 9.81;
constexpr double kVolume = 4 * kHalfWidth * kHalfWidth * kHeight;  // 3,136 particles

double huppert_front(double nu, double t) {
  const double mu = kDensity * nu;
  return 0.894 * std::pow(kDensity * kG * kVolume * kVolume * kVolume * t / (3 * mu), 0.125);
}

// A 0.14 x 0.14 x 0.16 m column in the middle of a 0.7 m square tank, run to t; the front is the
// 99th percentile of the particles' distances from the axis, plus half a spacing (the liquid's
// edge). The tank's walls are never reached.
double front_at(double nu, double t) {
  const nlohmann::json liquid = {{"type", "liquid"},        {"density", kDensity},
                                 {"viscosity", nu},         {"boundary_viscosity", nu},
                                 {"implicit_viscosity", 1}, {"solver", "pcisph"}};
  const double c = kTank / 2;
  const nlohmann::json doc = {
      {"name", "viscous_column"},
      {"gravity", {0, -kG, 0}},
      {"particle_spacing", kSpacing},
      {"materials", {{"liquid", liquid}, {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {kTank, 0.3, kTank}}}}},
      {"fluid_blocks",
       {{{"material", "liquid"},
         {"min", {c - kHalfWidth, 0, c - kHalfWidth}},
         {"max", {c + kHalfWidth, kHeight, c + kHalfWidth}}}}},
      {"time", {{"end", t}, {"dt_max", 0.005}}}};
  TestWorld tw(doc, 2);
  tw.run_until(t);
  const Particles& p = tw.world->particles();
  std::vector<double> r;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const double dx = double(p.position[i].x) - c, dz = double(p.position[i].z) - c;
    r.push_back(std::sqrt(dx * dx + dz * dz));
  }
  std::sort(r.begin(), r.end());
  return r[std::size_t(0.99 * double(r.size()))] + 0.5 * kSpacing;
}

// At t = 4 s (the fronts have spread to 2.5 and 3.2 times the column's half-width) each front is
// within 20 % of r_N (measured: 0.92 and 0.96 of it), and their ratio within 20 % of 5^(1/8).
TEST(ViscousGravityCurrent, HoneySpreadsAsHuppertsCurrentAndSlowerThanAThinnerLiquid) {
  const double t = 4.0;
  const double honey = front_at(0.1, t), thinner = front_at(0.02, t);
  const double honey_theory = huppert_front(0.1, t), thinner_theory = huppert_front(0.02, t);
  std::printf("fronts at %.1f s: nu 0.1 %.4f m (Huppert %.4f), nu 0.02 %.4f m (Huppert %.4f)\n", t,
              honey, honey_theory, thinner, thinner_theory);
  EXPECT_NEAR(honey, honey_theory, 0.2 * honey_theory);
  EXPECT_NEAR(thinner, thinner_theory, 0.2 * thinner_theory);
  const double ratio = thinner / honey, expected = std::pow(5.0, 0.125);
  EXPECT_NEAR(ratio, expected, 0.2 * expected);
  record_validation("honey column's front (nu 0.1) / r_N at 4 s",
                    "Huppert 1982, axisymmetric viscous gravity current", "1", "within 20 %",
                    honey / honey_theory);
  record_validation("front of nu 0.02 / front of nu 0.1 at 4 s",
                    "Huppert 1982: r_N proportional to mu^(-1/8)", "1.223", "within 20 %", ratio);
}

}  // namespace
}  // namespace upf::testing
