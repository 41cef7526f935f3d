// Ray-parity inside test against analytic shapes: a box on the particle lattice (points on its
// faces' planes and its edges' lines are the hard case for parity), the icosphere against a
// ball's radius, and the torus's hole. Plus the fluid carving that uses it.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/bodies/fluid_carving.h"
#include "coupling/mesh/mesh_inside_test.h"
#include "coupling/mesh/mesh_loader.h"
#include "test_mesh_support.h"

namespace upf {
namespace {

using mesh_test::asset;

TEST(MeshInside, BoxOnTheLatticeMatchesItsExtentEverywhere) {
  // Side 1 centred at the origin, probed on a lattice that lines up with its faces and edges.
  const MeshInsideTest box(load_mesh(asset("unit_box.obj")), 0.1);
  int wrong = 0, checked = 0;
  for (int i = -7; i <= 7; ++i)
    for (int j = -7; j <= 7; ++j)
      for (int k = -7; k <= 7; ++k) {
        const Eigen::Vector3d x = 0.1 * Eigen::Vector3d(i, j, k) + Eigen::Vector3d(0.013, 0, 0);
        if (std::abs(std::abs(x.x()) - 0.5) < 1e-9 || std::abs(std::abs(x.y()) - 0.5) < 1e-9 ||
            std::abs(std::abs(x.z()) - 0.5) < 1e-9)
          continue;  // on a face: either answer is right
        const bool expected = x.cwiseAbs().maxCoeff() < 0.5;
        wrong += box.contains(x) != expected;
        ++checked;
      }
  EXPECT_EQ(wrong, 0) << "of " << checked;
}

TEST(MeshInside, IcosphereAgreesWithItsBallAwayFromTheFacets) {
  // Radius 0.5; the facets lie between the inscribed and circumscribed radii (within 1.5 %).
  const MeshInsideTest sphere(load_mesh(asset("icosphere.ply")), 0.05);
  int wrong = 0;
  for (int i = -12; i <= 12; ++i)
    for (int j = -12; j <= 12; ++j)
      for (int k = -12; k <= 12; ++k) {
        const Eigen::Vector3d x = 0.05 * Eigen::Vector3d(i, j, k);
        const double r = x.norm();
        if (std::abs(r - 0.5) < 0.02) continue;
        wrong += sphere.contains(x) != (r < 0.5);
      }
  EXPECT_EQ(wrong, 0);
}

TEST(MeshInside, TorusHoleIsOutside) {
  const TriangleMesh torus = load_mesh(asset("torus.glb"));
  const Eigen::AlignedBox3d box = bounding_box(torus);
  const MeshInsideTest inside(torus, 0.02);
  EXPECT_FALSE(inside.contains(box.center()));
  EXPECT_FALSE(inside.contains(box.max() + Eigen::Vector3d::Constant(0.1)));
}

TEST(FluidCarving, RemovesLiquidInsideAndNearTheSurfaceOnly) {
  // A unit box of side 0.2 at the origin in a lattice of liquid at spacing 0.02, plus frozen
  // particles inside it that must stay.
  BodySource body;
  MeshTransform scaled;
  scaled.scale = Eigen::Vector3d::Constant(0.2);
  body.mesh = load_mesh(asset("unit_box.obj"), scaled);
  // One outer-layer sample half a spacing under the face x = 0.1: the surface point it stands
  // for, (0.1, 0.009, 0.009), is 0.009 from the lattice point (0.109, 0.009, 0.009), which is
  // outside the box but within half a spacing of the surface.
  body.samples = {{0.1 - 0.01, 0.009, 0.009}};
  body.normals = {{1, 0, 0}};
  Particles p;
  for (int i = -10; i < 10; ++i)
    for (int j = -10; j < 10; ++j)
      for (int k = -10; k < 10; ++k)
        p.add(Vec3{Real(0.02 * i + 0.009), Real(0.02 * j + 0.009), Real(0.02 * k + 0.009)}, {},
              Real(1), ParticleType::Liquid, 0);
  p.add(Vec3{0, 0, 0}, {}, Real(1), ParticleType::Frozen, 0);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    const bool in = std::abs(x.x) < 0.1 && std::abs(x.y) < 0.1 && std::abs(x.z) < 0.1;
    const double dx = x.x - 0.1, dy = x.y - 0.009, dz = x.z - 0.009;
    const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    expected += p.type[i] == ParticleType::Liquid && (in || d < 0.01);
  }
  ASSERT_GT(expected, 1000u);
  const std::size_t before = p.size();
  EXPECT_EQ(carve_fluid(p, body, 0.02), expected);
  EXPECT_EQ(p.size(), before - expected);
  EXPECT_EQ(p.count(ParticleType::Frozen), 1u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    EXPECT_FALSE(std::abs(p.position[i].x) < 0.1 && std::abs(p.position[i].y) < 0.1 &&
                 std::abs(p.position[i].z) < 0.1);
  }
}

}  // namespace
}  // namespace upf
