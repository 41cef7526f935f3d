// Wetting by adhesion (Akinci et al. 2013, eq. 6-7): a drop on a flat wall spreads further, to a
// smaller contact angle, as its adhesion rises (Young 1805). The angle comes from the drop's
// shape, a spherical cap at this Bond number: with height h and volume V, the sphere's radius is
// r = V / (pi h^2) + h / 3 and cos(theta) = 1 - h / r.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpacing = 0.0005;  // m
constexpr double kRadius = 0.003;    // m, the drop's before it lands

// A drop of radius R = 6 spacings (3 mm) resting on the floor of a 1.4 x 0.8 x 1.4 cm box, under a
// gravity of 0.5 m/s^2 (Bond number rho g R^2 / sigma = 0.06: a cap, not a puddle).
// `wetting`: the water's key toward the walls, "adhesion" (a ratio) or "contact_angle" (degrees).
nlohmann::json drop_on_a_wall(const std::string& wetting, double value) {
  const double c = 0.007, bottom = 0;
  nlohmann::json water = {{"type", "liquid"},
                          {"density", 1000},
                          {"viscosity", 2e-4},
                          {"surface_tension", 0.0728},
                          {"solver", "pcisph"}};
  water[wetting] = {{"walls", value}};
  return {
      {"name", "sessile_drop"},
      {"gravity", {0, -0.5, 0}},
      {"particle_spacing", kSpacing},
      {"materials", {{"water", water}, {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.014, 0.008, 0.014}}}}},
      {"fluid_blocks",
       {{{"material", "water"},
         {"shape", "ball"},
         {"min", {c - kRadius, bottom, c - kRadius}},
         {"max", {c + kRadius, bottom + 2 * kRadius, c + kRadius}}}}},
      {"time", {{"dt_max", 0.0005}}}};
}

// The contact angle in degrees, from the cap's height and volume.
double cap_angle(const Particles& p) {
  double top = 0, n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Liquid) {
      top = std::max(top, double(p.position[i].y));
      n += 1;
    }
  const double h = top + 0.5 * kSpacing;  // the floor's face is y = 0
  const double volume = n * kSpacing * kSpacing * kSpacing;
  const double r = volume / (kPi * h * h) + h / 3;
  return std::acos(std::clamp(1 - h / r, -1.0, 1.0)) * 180 / kPi;
}

// The contact angle in degrees after `seconds`.
double contact_angle(double adhesion_ratio, double seconds) {
  TestWorld t(drop_on_a_wall("adhesion", adhesion_ratio), 2);
  t.run_until(seconds);
  return cap_angle(t.world->particles());
}

// Young: cos(theta) = W_adhesion / sigma - 1 grows with the work of adhesion, which is linear in
// beta; so the angle falls as the ratio beta / gamma rises: 0, 4, 8 gave 180, 139 and 114 degrees
// after 0.1 s (docs/surface-tension.md: the drop still spreads by a few degrees per 0.1 s, so these
// are not yet equilibrium angles, and no angle is asserted for a ratio).
TEST(ContactAngle, FallsAsTheAdhesionRatioRises) {
  double previous = 0;
  for (const double ratio : {0.0, 4.0, 8.0}) {
    const double angle = contact_angle(ratio, 0.1);
    std::printf("adhesion ratio %.0f: contact angle %.1f degrees after 0.1 s\n", ratio, angle);
    record_validation("contact angle [deg] of a drop on a wall after 0.1 s, adhesion ratio " +
                          std::to_string(int(ratio)),
                      "Young 1805: falls as the work of adhesion rises", "falling",
                      "10 degrees below the smaller ratio's", angle, "deg");
    if (ratio > 0) {
      EXPECT_LT(angle, previous - 10) << "ratio " << ratio;
    }
    previous = angle;
  }
  EXPECT_LT(previous, 135);  // the largest ratio wets visibly
}

// The scene key "contact_angle" (adhesion_contact_angle.h's measured mapping) gives the drop the
// angle asked for within 10 degrees, the mean of its cap angle at 0.4, 0.5 and 0.6 s.
TEST(ContactAngle, TheAngleAskedForIsReachedWithinTenDegrees) {
  for (const double asked : {90.0, 120.0, 150.0}) {
    TestWorld t(drop_on_a_wall("contact_angle", asked), 2);
    double sum = 0;
    for (const double at : {0.4, 0.5, 0.6}) {
      t.run_until(at);
      sum += cap_angle(t.world->particles());
    }
    const double angle = sum / 3;
    std::printf("contact_angle %.0f: the drop rests at %.1f degrees\n", asked, angle);
    record_validation("contact angle [deg] of a drop on a wall asked for " +
                          std::to_string(int(asked)) + " degrees, mean over 0.4-0.6 s",
                      "Young 1805 equilibrium; the mapping measured in adhesion_contact_angle.h",
                      std::to_string(int(asked)), "within 10 degrees", angle, "deg");
    EXPECT_NEAR(angle, asked, 10) << "asked for " << asked;
  }
}

}  // namespace
}  // namespace upf::testing
