// Angle of repose: a quasi-two-dimensional column of grains collapses both ways into a heap
// whose slopes steepen with the sliding friction (the experiments of Zhou et al.
// 2002, "Rolling friction in the dynamic simulation of sandpile formation", Physica A 269, and
// the DEM studies since). The angles are printed; the test asserts that they grow with mu and
// stay between the angle of a frictionless pile (near 0) and 45 degrees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The slope angle, in degrees, of the heap left by a column 2 x half_width wide: the mean of its
// two sides, each a least-squares line through the top of each 2-cm column of grains between
// 20 % and 80 % of the heap's height.
double heap_angle(double mu, double half_width) {
  const double s = 0.02;
  nlohmann::json doc = {
      {"particle_spacing", s},
      {"materials",
       {{"sand",
         {{"type", "granular"},
          {"density", 2600},
          {"normal_stiffness", 2e4},
          {"restitution", 0.3},
          {"friction", mu},
          {"rolling_friction", 0.1}}},
        {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {1.2, 0.5, 0.06}}}}},
      {"granular_blocks",
       {{{"material", "sand"},
         {"min", {0.6 - half_width, 0, 0}},
         {"max", {0.6 + half_width, 0.4, 0.06}}}}},
      {"time", {{"dt_max", 0.002}}}};
  TestWorld t(doc, 2);
  t.run_until(2.0);
  const Particles& p = t.world->particles();
  std::map<int, double> top;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Granular) continue;
    const int column = int(std::floor(double(p.position[i].x) / s));
    top[column] = std::max(top.count(column) ? top[column] : 0.0, double(p.position[i].y));
  }
  double height = 0;
  for (const auto& [c, y] : top) height = std::max(height, y);
  double angle = 0;
  for (int side : {-1, 1}) {  // left of the middle (x < 0.6), then right
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (const auto& [c, y] : top) {
      const double x = (c + 0.5) * s;
      if (y < 0.2 * height || y > 0.8 * height || (x - 0.6) * side < 0) continue;
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
      ++n;
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    angle += 0.5 * std::atan(-side * slope) * 180 / kPi;
  }
  return angle;
}

// Two heaps (columns 32 and 24 cm wide), four slopes: a heap is one sample of a chaotic
// collapse, and a change of rounding moves a single slope by a few degrees.
double repose_angle(double mu) {
  return 0.5 * (heap_angle(mu, 0.16) + heap_angle(mu, 0.12));
}

TEST(DemRepose, AngleOfReposeGrowsWithFriction) {
  const double a2 = repose_angle(0.2), a5 = repose_angle(0.5), a8 = repose_angle(0.8);
  std::printf("angle of repose: mu 0.2 -> %.1f deg, 0.5 -> %.1f deg, 0.8 -> %.1f deg\n", a2, a5,
              a8);
  for (auto [mu, angle] : {std::pair{0.2, a2}, {0.5, a5}, {0.8, a8}})
    record_validation("angle of repose, mu = " + std::to_string(mu).substr(0, 3),
                      "heaps steepen with friction (Zhou et al. 2002)",
                      "grows with mu, under 45 deg", "2 < a(0.2) < a(0.5) < a(0.8) < 45", angle,
                      "deg");
  EXPECT_GT(a2, 2.0);
  EXPECT_LT(a2, a5);
  EXPECT_LT(a5, a8);
  EXPECT_LT(a8, 45.0);
}

}  // namespace
}  // namespace upf::testing
