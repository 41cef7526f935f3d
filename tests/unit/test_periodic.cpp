// Periodic domains (framework/world/periodic_box.h, periodic_domain.h): the box's geometry, the
// scene key's checks, and a world's images of its particles.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "framework/world/periodic_box.h"
#include "tests/physics/scene_helpers.h"

namespace upf {
namespace {

PeriodicBox box_x_and_z() {
  PeriodicBox box;
  box.periodic[0] = box.periodic[2] = true;
  box.lo = {0, 0, 0};
  box.hi = {1, 0, 2};
  return box;
}

TEST(PeriodicBox, WrapsPositionsIntoThePeriodAlongItsAxesOnly) {
  const PeriodicBox box = box_x_and_z();
  Vec3 x{Real(1.25), Real(-3), Real(-0.5)};
  box.wrap(x);
  EXPECT_DOUBLE_EQ(double(x.x), 0.25);
  EXPECT_DOUBLE_EQ(double(x.y), -3);  // not periodic: untouched
  EXPECT_DOUBLE_EQ(double(x.z), 1.5);
  Vec3 on_face{1, 0, 0};  // hi belongs to the next period: [lo, hi)
  box.wrap(on_face);
  EXPECT_DOUBLE_EQ(double(on_face.x), 0);
}

std::vector<Vec3> shifts_of(const PeriodicBox& box, const Vec3& x, Real reach) {
  std::vector<Vec3> shifts;
  box.for_each_image_shift(x, reach, [&](const Vec3& s) { shifts.push_back(s); });
  return shifts;
}

TEST(PeriodicBox, NamesTheImagesWithinReachOfTheBox) {
  const PeriodicBox box = box_x_and_z();
  const Real reach = Real(0.1);
  EXPECT_TRUE(shifts_of(box, {Real(0.5), 0, Real(1)}, reach).empty());  // far from every face
  // Near x's low face: one image, a period up.
  const auto low = shifts_of(box, {Real(0.05), 5, Real(1)}, reach);
  ASSERT_EQ(low.size(), 1u);
  EXPECT_EQ(low[0], (Vec3{1, 0, 0}));
  // Near x's high face and z's low face: three images (x, z, and the corner).
  const auto corner = shifts_of(box, {Real(0.95), 0, Real(0.02)}, reach);
  ASSERT_EQ(corner.size(), 3u);
  EXPECT_EQ(corner[0], (Vec3{-1, 0, 0}));
  EXPECT_EQ(corner[1], (Vec3{0, 0, 2}));
  EXPECT_EQ(corner[2], (Vec3{-1, 0, 2}));
  // Periodic in all three, in a corner: seven.
  PeriodicBox cube;
  cube.periodic[0] = cube.periodic[1] = cube.periodic[2] = true;
  cube.hi = {1, 1, 1};
  EXPECT_EQ(shifts_of(cube, {Real(0.01), Real(0.99), Real(0.01)}, reach).size(), 7u);
}

// A channel periodic in x and z at spacing 0.01 (support radius 0.02).
nlohmann::json channel(double period_x) {
  return {
      {"name", "channel"},
      {"particle_spacing", 0.01},
      {"gravity", {1, 0, 0}},
      {"materials",
       {{"water", {{"type", "liquid"}, {"solver", "pcisph"}}}, {"walls", {{"type", "frozen"}}}}},
      {"periodic", {{"x", {0, period_x}}, {"z", {0, 0.06}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {period_x, 0.1, 0.06}}}}},
      {"fluid_blocks",
       {{{"material", "water"}, {"min", {0, 0, 0}}, {"max", {period_x, 0.1, 0.06}}}}}};
}

// The problem the reader reports at `where`, or "" when it reads the scene.
std::string problem_at(const nlohmann::json& doc, const std::string& where) {
  try {
    read_scene(doc, testing::builtin_registry(), "test");
  } catch (const InputError& e) {
    for (const auto& problem : e.problems())
      if (problem.where == "test:" + where) return problem.message;
    return "(elsewhere: " + std::string(e.what()) + ")";
  }
  return "";
}

TEST(PeriodicScene, ReadsTheAxesAndBuildsWallsOnlyAcrossTheOthers) {
  const SceneDescription scene = read_scene(channel(0.06), testing::builtin_registry(), "test");
  const PeriodicBox& box = scene.world.periodic;
  EXPECT_TRUE(box.periodic[0] && !box.periodic[1] && box.periodic[2]);
  EXPECT_NEAR(double(box.period(0)), 0.06, 1e-7);
  testing::TestWorld t(channel(0.06), 1);
  const Particles& p = t.world->particles();
  std::size_t walls = 0, liquid = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    (p.type[i] == ParticleType::Frozen ? walls : liquid) += 1;
    // No wall particle outside the period: the walls across x and z are left out.
    if (p.type[i] == ParticleType::Frozen) {
      EXPECT_GT(p.position[i].x, 0);
      EXPECT_LT(p.position[i].x, Real(0.06));
    }
  }
  EXPECT_EQ(liquid, 6u * 10u * 6u);
  EXPECT_EQ(walls, 2u * 2u * 6u * 6u);  // two layers below and above
  EXPECT_EQ(p.ghost_count(), 0u);       // images live only inside a step
}

TEST(PeriodicScene, RefusesWhatCannotRepeatWithThePathAndTheReason) {
  EXPECT_NE(problem_at(channel(0.03), "/periodic/x").find("must exceed two support radii"),
            std::string::npos);
  EXPECT_NE(problem_at(channel(0.065), "/periodic/x").find("6.5 particle spacings"),
            std::string::npos);
  auto doc = channel(0.06);
  doc["containers"][0]["max"][0] = 0.05;
  EXPECT_NE(problem_at(doc, "/containers/0").find("spans the period"), std::string::npos);
  doc = channel(0.06);
  doc["fluid_blocks"][0]["max"][2] = 0.07;
  doc["containers"][0]["max"][2] = 0.07;
  EXPECT_NE(problem_at(doc, "/fluid_blocks/0").find("outside the period"), std::string::npos);
  doc = channel(0.06);
  doc["periodic"]["x"] = {0.06, 0};
  EXPECT_NE(problem_at(doc, "/periodic/x").find("expected lo < hi"), std::string::npos);
  doc["periodic"]["x"] = "all";
  EXPECT_NE(problem_at(doc, "/periodic/x").find("expected [lo, hi]"), std::string::npos);
  doc = channel(0.06);
  doc["periodic"]["w"] = {0, 1};
  EXPECT_NE(problem_at(doc, "/periodic/w"), "");
  doc = channel(0.06);
  doc["materials"]["sand"] = {{"type", "granular"}, {"solver", "dem_linear"}};
  EXPECT_NE(problem_at(doc, "/materials/sand").find("not supported yet"), std::string::npos)
      << problem_at(doc, "/materials/sand");
}

// Water filling the box [0, size] that repeats along every axis, moving at `velocity`: no walls,
// no surface.
nlohmann::json water_filling_a_periodic_box(const std::array<double, 3>& size,
                                            const std::array<double, 3>& velocity) {
  return {{"name", "periodic_box"},
          {"particle_spacing", 0.01},
          {"gravity", {0, 0, 0}},
          {"materials", {{"water", {{"type", "liquid"}, {"solver", "pcisph"}}}}},
          {"periodic", {{"x", {0, size[0]}}, {"y", {0, size[1]}}, {"z", {0, size[2]}}}},
          {"fluid_blocks",
           {{{"material", "water"}, {"min", {0, 0, 0}}, {"max", size}, {"velocity", velocity}}}}};
}

// A liquid at rest filling a box periodic in every axis has no surface anywhere: every particle
// sums the lattice's full kernel sum, and PCISPH keeps every particle where it is.
TEST(PeriodicWorld, ALiquidFillingAPeriodicBoxHasTheRestDensityEverywhere) {
  const nlohmann::json doc = water_filling_a_periodic_box({0.06, 0.05, 0.07}, {0, 0, 0});
  testing::TestWorld t(doc, 2);
  for (int s = 0; s < 20; ++s) t.world->step(0.002);
  const Particles& p = t.world->particles();
  ASSERT_EQ(p.size(), 6u * 5u * 7u);
  const std::vector<Real>* density = p.find_scalar("density");
  ASSERT_NE(density, nullptr);
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Without the images a face particle sums about half a kernel: 40 % below.
    EXPECT_NEAR(double((*density)[i]), 1000, 1e-3 * 1000) << "particle " << i;
    EXPECT_LT(double(std::sqrt(squared_norm(p.velocity[i]))), 1e-6);
  }
}

// Particles that cross a face come back through the opposite one, at the same speed.
TEST(PeriodicWorld, AUniformStreamWrapsAroundAndStaysUniform) {
  const nlohmann::json doc = water_filling_a_periodic_box({0.06, 0.05, 0.05}, {0.5, 0, 0.25});
  testing::TestWorld t(doc, 2);
  for (int s = 0; s < 100; ++s) t.world->step(0.002);  // 0.1 m in x: past the period
  const Particles& p = t.world->particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(p.position[i].x, 0);
    EXPECT_LT(p.position[i].x, Real(0.06));
    EXPECT_NEAR(double(p.velocity[i].x), 0.5, 1e-6);
    EXPECT_NEAR(double(p.velocity[i].z), 0.25, 1e-6);
  }
}

}  // namespace
}  // namespace upf
