// The extent probe (framework/run/probes.h): the liquid's largest or smallest coordinate, at the
// particle centres or, with "surface", half a spacing further out, as the height probe reports
// a free surface; and the scene reader's check of the "surface" key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "framework/run/probes.h"
#include "tests/physics/scene_helpers.h"

namespace upf {
namespace {

constexpr Real kSpacing = Real(0.02);

Particles three_liquid_and_a_wall() {
  Particles p;
  p.add(Vec3{Real(0.10), Real(0.01), 0}, Vec3{}, 1, ParticleType::Liquid, 0);
  p.add(Vec3{Real(0.30), Real(0.01), 0}, Vec3{}, 1, ParticleType::Liquid, 0);
  p.add(Vec3{Real(0.50), Real(0.21), 0}, Vec3{}, 1, ParticleType::Liquid, 0);
  p.add(Vec3{Real(0.90), Real(0.01), 0}, Vec3{}, 1, ParticleType::Frozen, 1);  // not liquid
  return p;
}

ProbeDesc extent(bool max_side, bool surface) {
  ProbeDesc probe;
  probe.kind = ProbeKind::Extent;
  probe.axis = 0;
  probe.max_side = max_side;
  probe.surface = surface;
  return probe;
}

TEST(ExtentProbe, ReportsCentresOrTheSurfaceHalfASpacingOut) {
  const Particles p = three_liquid_and_a_wall();
  EXPECT_DOUBLE_EQ(evaluate_probe(extent(true, false), p, kSpacing), double(Real(0.50)));
  EXPECT_DOUBLE_EQ(evaluate_probe(extent(false, false), p, kSpacing), double(Real(0.10)));
  EXPECT_DOUBLE_EQ(evaluate_probe(extent(true, true), p, kSpacing),
                   double(Real(0.50)) + 0.5 * double(kSpacing));
  EXPECT_DOUBLE_EQ(evaluate_probe(extent(false, true), p, kSpacing),
                   double(Real(0.10)) - 0.5 * double(kSpacing));
}

TEST(ExtentProbe, CountsOnlyTheRegionAndIsNanWithoutLiquid) {
  const Particles p = three_liquid_and_a_wall();
  ProbeDesc near_floor = extent(true, true);
  near_floor.region = Box{Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(2, 0.05, 1)};
  EXPECT_DOUBLE_EQ(evaluate_probe(near_floor, p, kSpacing),
                   double(Real(0.30)) + 0.5 * double(kSpacing));
  ProbeDesc empty = extent(true, true);
  empty.region = Box{Eigen::Vector3d(5, 5, 5), Eigen::Vector3d(6, 6, 6)};
  EXPECT_TRUE(std::isnan(evaluate_probe(empty, p, kSpacing)));
}

TEST(ExtentProbe, SceneReaderTakesSurfaceAsABooleanOnly) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.05;
  doc["probes"] = nlohmann::json::array(
      {{{"name", "front"}, {"type", "extent"}, {"axis", "x"}, {"surface", true}}});
  const SceneDescription scene = read_scene(doc, testing::builtin_registry(), "test");
  ASSERT_EQ(scene.probes.size(), 1u);
  EXPECT_TRUE(scene.probes[0].surface);

  doc["probes"][0]["surface"] = "yes";
  std::string message;
  try {
    read_scene(doc, testing::builtin_registry(), "test");
  } catch (const InputError& e) {
    for (const auto& problem : e.problems())
      if (problem.where == "test:/probes/0/surface") message = problem.message;
  }
  EXPECT_EQ(message, "expected true or false");
}

}  // namespace
}  // namespace upf
