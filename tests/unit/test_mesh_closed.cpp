// Closedness as a dynamic body needs it: every edge shared by exactly two triangles that run it
// in opposite directions. Checked on the shipped meshes (closed by construction in
// scripts/make_assets.py) and on hand-made defects, one of each kind.
#include <gtest/gtest.h>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mesh_loader.h"
#include "test_mesh_support.h"

namespace upf {
namespace {

using mesh_test::asset;
using mesh_test::input_error_text;
using mesh_test::test_mesh;

TEST(MeshClosed, ShippedMeshesAreClosed) {
  for (const char* name : {"unit_box.obj", "icosphere.ply", "torus.glb", "l_block_mm.stl"}) {
    const TriangleMesh mesh = load_mesh(asset(name));
    EXPECT_TRUE(is_closed(mesh)) << name;
    EXPECT_NO_THROW(require_closed(mesh, "")) << name;
  }
}

TEST(MeshClosed, MissingFaceLeavesFourBoundaryEdges) {
  const TriangleMesh mesh = load_mesh(test_mesh("open_box.obj"));
  const ClosedMeshReport report = check_closed(mesh);
  EXPECT_EQ(report.boundary_edges, 4u);
  EXPECT_EQ(report.non_manifold_edges, 0u);
  EXPECT_EQ(report.misoriented_edges, 0u);
  const std::string text = input_error_text([&] { require_closed(mesh, "/bodies/0/mesh"); });
  EXPECT_EQ(text, "/bodies/0/mesh: mesh file '" + mesh.source +
                      "': is not a closed, consistently oriented surface, which a dynamic body "
                      "needs: 4 edges used by one triangle only (holes)");
}

TEST(MeshClosed, OneFlippedTriangleMisorientsItsThreeEdges) {
  TriangleMesh mesh = load_mesh(asset("unit_box.obj"));
  std::swap(mesh.triangles[5][1], mesh.triangles[5][2]);
  const ClosedMeshReport report = check_closed(mesh);
  EXPECT_FALSE(report.closed());
  EXPECT_EQ(report.misoriented_edges, 3u);
  EXPECT_EQ(report.boundary_edges, 0u);
}

TEST(MeshClosed, ThreeTrianglesOnOneEdgeAreNonManifold) {
  TriangleMesh fan;
  fan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fan.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const ClosedMeshReport report = check_closed(fan);
  EXPECT_EQ(report.non_manifold_edges, 1u);
  EXPECT_EQ(report.boundary_edges, 6u);
}

}  // namespace
}  // namespace upf
