// The extent probe (framework/run/probes.h): the liquid's largest or smallest coordinate, at the
// particle centres or, with "surface", half a spacing further out, as the height probe reports
// a free surface; and the scene reader's check of the "surface" key. The height probe's volume
// method (a wave gauge: liquid volume per unit area) and the pressure probe's kernel method
// (Shepard interpolation, exact for a linear field), checked against analytic values.
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

// A block of liquid on a cubic lattice: n_x x n_y x n_z particles of spacing s, centres at
// (i + 1/2) s, and a `pressure` field p = a + b y.
Particles liquid_block(int nx, int ny, int nz, double a, double b) {
  Particles p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        p.add(Vec3{Real((i + 0.5) * kSpacing), Real((j + 0.5) * kSpacing),
                   Real((k + 0.5) * kSpacing)},
              Vec3{}, 1, ParticleType::Liquid, 0);
  auto& pressure = p.scalar_field("pressure");
  for (std::size_t i = 0; i < p.size(); ++i) pressure[i] = Real(a + b * double(p.position[i].y));
  return p;
}

// A still block of 12 layers is 12 s deep. The volume gauge reads that within the lattice
// quadrature error of its kernel (0.7 % at the default 3 s radius), and a droplet of one particle
// 10 s above the surface moves it by one particle's volume under the kernel, not by 10 s as it
// moves the top-particle reading.
TEST(HeightProbe, VolumeMethodReadsTheDepthAndBarelySeesSpray) {
  Particles p = liquid_block(20, 12, 20, 0, 0);
  const double depth = 12 * double(kSpacing);
  ProbeDesc gauge;
  gauge.kind = ProbeKind::Height;
  gauge.axis = 1;
  gauge.at = Eigen::Vector2d(10.3 * kSpacing, 9.8 * kSpacing);
  gauge.radius = 3 * kSpacing;
  gauge.method = ProbeMethod::Volume;
  EXPECT_NEAR(evaluate_probe(gauge, p, kSpacing), depth, 0.007 * depth);
  ProbeDesc top = gauge;
  top.method = ProbeMethod::Top;
  EXPECT_NEAR(evaluate_probe(top, p, kSpacing), depth, 1e-6);

  p.add(Vec3{Real(10.3 * kSpacing), Real(22 * kSpacing), Real(9.8 * kSpacing)}, Vec3{}, 1,
        ParticleType::Liquid, 0);
  EXPECT_NEAR(evaluate_probe(top, p, kSpacing), 22.5 * double(kSpacing), 1e-6);
  // One particle at the gauge's axis adds s^3 W(0) = s^3 7 / (pi (3 s)^2) = 0.25 s.
  EXPECT_NEAR(evaluate_probe(gauge, p, kSpacing), depth + 0.248 * double(kSpacing), 0.007 * depth);
}

// Shepard interpolation reproduces a linear field at a point inside the liquid exactly (up to
// round-off) when the neighbourhood is symmetric, and at a wall, where only one side has
// liquid, it reads the pressure there to first order better than the sphere mean: the mean of
// p = a + b y over the half ball under a wall at y = H sits 3/8 r below it, the kernel-weighted
// mean closer.
TEST(PressureProbe, KernelMethodInterpolatesAndReadsAWallBetterThanTheMean) {
  const double a = 5000, b = -9810;
  const Particles p = liquid_block(20, 20, 20, a, b);
  ProbeDesc sensor;
  sensor.kind = ProbeKind::Pressure;
  sensor.center = Eigen::Vector3d(10 * kSpacing, 10 * kSpacing, 10 * kSpacing);
  sensor.radius = 2 * kSpacing;
  sensor.method = ProbeMethod::Kernel;
  const double inside = a + b * sensor.center.y();
  EXPECT_NEAR(evaluate_probe(sensor, p, kSpacing), inside, 1e-3 * std::abs(b) * kSpacing);

  sensor.center.y() = 20 * kSpacing;  // the block's top face
  const double at_wall = a + b * sensor.center.y();
  ProbeDesc mean = sensor;
  mean.method = ProbeMethod::Mean;
  const double kernel_error = std::abs(evaluate_probe(sensor, p, kSpacing) - at_wall);
  const double mean_error = std::abs(evaluate_probe(mean, p, kSpacing) - at_wall);
  EXPECT_LT(kernel_error, 0.7 * mean_error);
}

TEST(Probes, SceneReaderTakesTheMethodsOfEachTypeOnly) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.05;
  doc["probes"] = nlohmann::json::array(
      {{{"name", "gauge"}, {"type", "height"}, {"at", {0.5, 0.2}}, {"method", "volume"}},
       {{"name", "sensor"},
        {"type", "pressure"},
        {"center", {0.5, 0.1, 0.2}},
        {"method", "kernel"}},
       {{"name", "plain"}, {"type", "height"}, {"at", {0.5, 0.2}}}});
  const SceneDescription scene = read_scene(doc, testing::builtin_registry(), "test");
  ASSERT_EQ(scene.probes.size(), 3u);
  EXPECT_EQ(scene.probes[0].method, ProbeMethod::Volume);
  EXPECT_DOUBLE_EQ(scene.probes[0].radius, 3 * 0.05);
  EXPECT_EQ(scene.probes[1].method, ProbeMethod::Kernel);
  EXPECT_EQ(scene.probes[2].method, ProbeMethod::Top);
  EXPECT_DOUBLE_EQ(scene.probes[2].radius, 2 * 0.05);

  doc["probes"][1]["method"] = "volume";  // a height method on a pressure probe
  std::string message;
  try {
    read_scene(doc, testing::builtin_registry(), "test");
  } catch (const InputError& e) {
    for (const auto& problem : e.problems())
      if (problem.where == "test:/probes/1/method") message = problem.message;
  }
  EXPECT_EQ(message, "unknown method 'volume' (allowed: 'mean', 'kernel')");
}

}  // namespace
}  // namespace upf
