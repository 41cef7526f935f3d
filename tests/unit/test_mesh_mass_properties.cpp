// Mass properties of closed meshes (divergence theorem, Mirtich 1996 / Eberly 2002) against
// closed-form values: a box, m (a^2 + b^2) / 12 about each axis (exact: the mesh is the solid);
// the same box scaled, rotated and moved, I = R I0 R^T about its centre; a non-convex L-shaped
// block, exact as two boxes joined (parallel axis theorem); a sphere, V = 4/3 pi r^3 and
// I = 2/5 m r^2, and a torus, V = 2 pi^2 R r^2, I_zz = m (R^2 + 3/4 r^2),
// I_xx = m (R^2 / 2 + 5/8 r^2): tessellations, within 1 % of the smooth shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mass_properties.h"
#include "coupling/mesh/mesh_loader.h"
#include "test_mesh_support.h"

namespace upf {
namespace {

using mesh_test::asset;
using mesh_test::input_error_text;
using mesh_test::test_mesh;
using std::numbers::pi;

// Solid box of sides a, b, c: inertia about its centre (a standard table entry).
Eigen::Matrix3d box_inertia(double mass, double a, double b, double c) {
  return Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b).asDiagonal() * (mass / 12.0);
}

double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

TEST(MeshMassProperties, UnitBoxIsExact) {
  const double density = 1000;
  const MassProperties p = mass_properties(load_mesh(asset("unit_box.obj")), density, "");
  EXPECT_NEAR(p.volume, 1.0, 1e-14);
  EXPECT_NEAR(p.mass, 1000.0, 1e-11);
  EXPECT_LT(p.center_of_mass.norm(), 1e-15);
  EXPECT_TRUE(p.inertia.isApprox(box_inertia(1000, 1, 1, 1), 1e-14)) << p.inertia;
}

TEST(MeshMassProperties, TransformedBoxRotatesItsInertia) {
  MeshTransform transform;
  transform.scale = {2, 3, 4};
  transform.rotation = rotation_from_axis_angle_degrees({1, 1, 0}, 30);
  transform.position = {5, -2, 7};
  const double density = 7.5;
  const MassProperties p =
      mass_properties(load_mesh(asset("unit_box.obj"), transform), density, "");
  const double mass = density * 24;
  EXPECT_NEAR(p.mass, mass, 1e-12 * mass);
  EXPECT_LT((p.center_of_mass - transform.position).norm(), 1e-13);
  const Eigen::Matrix3d r = transform.rotation.toRotationMatrix();
  const Eigen::Matrix3d expected = r * box_inertia(mass, 2, 3, 4) * r.transpose();
  EXPECT_LT((p.inertia - expected).norm(), 1e-12 * expected.norm()) << p.inertia;
}

TEST(MeshMassProperties, NonConvexLBlockIsExact) {
  // In metres: a 0.04 x 0.02 x 0.02 bar at the origin plus a 0.02 x 0.02 x 0.02 cube on it at
  // y = 0.02. Same density, so masses go as volumes.
  MeshTransform in_mm;
  in_mm.unit = 0.001;
  const double density = 2700;
  const MassProperties p = mass_properties(load_mesh(asset("l_block_mm.stl"), in_mm), density, "");
  const double m_bar = density * 0.04 * 0.02 * 0.02, m_cube = density * 0.02 * 0.02 * 0.02;
  const Eigen::Vector3d c_bar(0.02, 0.01, 0.01), c_cube(0.01, 0.03, 0.01);
  const double mass = m_bar + m_cube;
  const Eigen::Vector3d c = (m_bar * c_bar + m_cube * c_cube) / mass;
  auto shifted = [&c](double m, const Eigen::Vector3d& at) {  // parallel axis theorem
    const Eigen::Vector3d d = at - c;
    return Eigen::Matrix3d(m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
  };
  const Eigen::Matrix3d expected = box_inertia(m_bar, 0.04, 0.02, 0.02) + shifted(m_bar, c_bar) +
                                   box_inertia(m_cube, 0.02, 0.02, 0.02) + shifted(m_cube, c_cube);
  EXPECT_NEAR(p.volume, 0.04 * 0.04 * 0.02 - 0.02 * 0.02 * 0.02, 1e-18);
  EXPECT_NEAR(p.mass, mass, 1e-12 * mass);
  EXPECT_LT((p.center_of_mass - c).norm(), 1e-15);
  EXPECT_LT((p.inertia - expected).norm(), 1e-10 * expected.norm()) << p.inertia << "\nexpected\n"
                                                                    << expected;
}

TEST(MeshMassProperties, IcosphereWithinOnePercentOfTheSphere) {
  // 5120 triangles with vertices on the sphere: the polyhedron is inside it, 0.22 % less volume
  // and 0.36 % less inertia. Level 3 (1280 triangles) would miss inertia by 1.4 %.
  const double r = 0.5, density = 1000;
  const MassProperties p = mass_properties(load_mesh(asset("icosphere.ply")), density, "");
  const double mass = density * 4.0 / 3.0 * pi * r * r * r;
  const double inertia = 0.4 * mass * r * r;
  const double mass_error = relative_error(p.mass, mass);
  const double inertia_error = relative_error(p.inertia.diagonal().mean(), inertia);
  std::printf("[ sphere  ] mass error %.3f %%, inertia error %.3f %%\n", 100 * mass_error,
              100 * inertia_error);
  EXPECT_LT(mass_error, 0.01);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_LT(relative_error(p.inertia(axis, axis), inertia), 0.01) << "axis " << axis;
  EXPECT_LT(p.center_of_mass.norm(), 1e-9 * r);
  EXPECT_LT((p.inertia - Eigen::Matrix3d(p.inertia.diagonal().asDiagonal())).norm(),
            1e-3 * inertia);  // off-diagonal: symmetry of the icosahedron
}

TEST(MeshMassProperties, TorusWithinOnePercentOfTheSmoothTorus) {
  const double big = 0.35, small = 0.15, density = 500;
  const MassProperties p = mass_properties(load_mesh(asset("torus.glb")), density, "");
  const double mass = density * 2 * pi * pi * big * small * small;  // Pappus
  const double i_axis = mass * (big * big + 0.75 * small * small);
  const double i_across = mass * (0.5 * big * big + 0.625 * small * small);
  std::printf("[ torus   ] mass error %.3f %%, inertia errors %.3f %% (axis) %.3f %% (across)\n",
              100 * relative_error(p.mass, mass), 100 * relative_error(p.inertia(2, 2), i_axis),
              100 * relative_error(p.inertia(0, 0), i_across));
  EXPECT_LT(relative_error(p.mass, mass), 0.01);
  EXPECT_LT(relative_error(p.inertia(2, 2), i_axis), 0.01);
  EXPECT_LT(relative_error(p.inertia(0, 0), i_across), 0.01);
  EXPECT_LT(relative_error(p.inertia(1, 1), i_across), 0.01);
  EXPECT_LT(p.center_of_mass.norm(), 1e-12);
}

TEST(MeshMassProperties, InsideOutMeshGivesTheSameBody) {
  TriangleMesh mesh = load_mesh(asset("l_block_mm.stl"));
  const MassProperties outward = mass_properties(mesh, 1, "");
  flip_winding(mesh);
  EXPECT_LT(signed_volume(mesh), 0);
  const MassProperties inward = mass_properties(mesh, 1, "");
  EXPECT_NEAR(inward.volume, outward.volume, 1e-9);
  EXPECT_TRUE(inward.center_of_mass.isApprox(outward.center_of_mass, 1e-14));
  EXPECT_TRUE(inward.inertia.isApprox(outward.inertia, 1e-14));
  EXPECT_TRUE(orient_outward(mesh));
  EXPECT_GT(signed_volume(mesh), 0);
  EXPECT_FALSE(orient_outward(mesh));
}

TEST(MeshMassProperties, OpenMeshIsRefused) {
  const TriangleMesh mesh = load_mesh(test_mesh("open_box.obj"));
  const std::string text = input_error_text([&] { mass_properties(mesh, 1000, "/bodies/2/mesh"); });
  EXPECT_NE(text.find("/bodies/2/mesh: mesh file '" + mesh.source + "'"), std::string::npos)
      << text;
  EXPECT_NE(text.find("4 edges used by one triangle only"), std::string::npos) << text;
}

TEST(MeshMassProperties, FlatShellEnclosesNoVolume) {
  // Two triangles back to back: closed and consistently oriented, but flat.
  TriangleMesh shell;
  shell.source = "shell.obj";
  shell.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  shell.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_TRUE(is_closed(shell));
  const std::string text = input_error_text([&] { mass_properties(shell, 1, ""); });
  EXPECT_NE(text.find("shell.obj: mesh file 'shell.obj': encloses no volume"), std::string::npos)
      << text;
}

TEST(MeshMassProperties, DensityMustBePositive) {
  const TriangleMesh mesh = load_mesh(asset("unit_box.obj"));
  const std::string text = input_error_text([&] { mass_properties(mesh, -1, "/m"); });
  EXPECT_NE(text.find("density must be finite and positive, got -1 kg/m^3"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace upf
