// Granular blocks that start like experiments. A block of "packing": "random" (random sequential
// addition at a solid fraction of 0.25) falls and settles under gravity into a random packing.
// Its interior solid fraction must lie between random loose packing and random close packing
// of equal frictional spheres: 0.55 (Onoda & Liniger 1990, the loosest stable packing) to 0.64
// (Scott & Kilgour 1969). The default cubic lattice of touching grains (pi/6 = 0.524) instead
// stands as it was built: stacked columns that nothing disturbs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.005;  // half the spacing
constexpr double kWidth = 0.1;     // m, the container's x and z

// A 0.1 x 0.3 x 0.1 m block of 5 mm grains (friction 0.5) in a container of its size, settled
// for 0.8 s: the solid fraction of the grains whose centres lie two diameters or more from the
// walls and below the bed's top minus three diameters.
double settled_solid_fraction(const nlohmann::json& block_options) {
  nlohmann::json block = {{"material", "sand"}, {"min", {0, 0, 0}}, {"max", {kWidth, 0.3, kWidth}}};
  block.update(block_options);
  const nlohmann::json doc = {
      {"particle_spacing", 2 * kRadius},
      {"materials",
       {{"sand",
         {{"type", "granular"},
          {"density", 2500},
          {"normal_stiffness", 1e4},
          {"restitution", 0.3},
          {"friction", 0.5}}},
        {"walls", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {kWidth, 0.4, kWidth}}}}},
      {"granular_blocks", {block}},
      {"time", {{"dt_max", 0.002}}}};
  TestWorld t(doc, 2);
  t.run_until(0.8);
  const Particles& p = t.world->particles();
  double top = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Granular) top = std::max(top, double(p.position[i].y));
  const double margin = 4 * kRadius;
  const double y_max = top - 6 * kRadius;
  int inside = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Granular) continue;
    const Vec3& x = p.position[i];
    if (x.x < margin || x.x > kWidth - margin || x.z < margin || x.z > kWidth - margin ||
        x.y < margin || x.y > y_max)
      continue;
    ++inside;
  }
  const double region = (kWidth - 2 * margin) * (kWidth - 2 * margin) * (y_max - margin);
  const double fraction = inside * 4.0 / 3.0 * kPi * std::pow(kRadius, 3) / region;
  std::printf("%s: %zu grains, bed top %.4f m, interior solid fraction %.4f\n",
              block_options.dump().c_str(), p.count(ParticleType::Granular), top + kRadius,
              fraction);
  return fraction;
}

TEST(DemPacking, RandomBlockSettlesIntoARandomPacking) {
  const double fraction = settled_solid_fraction({{"packing", "random"}, {"solid_fraction", 0.25}});
  record_validation("settled solid fraction of a random block (mu 0.5)",
                    "random loose to close packing (Onoda & Liniger 1990; Scott & Kilgour 1969)",
                    "0.55-0.64", "in 0.55-0.64", fraction);
  EXPECT_GT(fraction, 0.55);
  EXPECT_LT(fraction, 0.64);
}

TEST(DemPacking, LatticeBlockStandsAsBuilt) {
  const double fraction = settled_solid_fraction(nlohmann::json::object());
  record_validation("settled solid fraction of a cubic lattice block (mu 0.5)",
                    "simple cubic packing of touching spheres, pi/6", "0.5236", "within 0.02",
                    fraction);
  EXPECT_NEAR(fraction, kPi / 6, 0.02);
}

}  // namespace
}  // namespace upf::testing
