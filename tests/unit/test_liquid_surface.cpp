// The liquid surface mesh (framework/output/liquid_surface.h). Reference: the liquid volume is
// mass / rho0 = N h^3 for N particles at spacing h (each stands for a cube of side h), and the
// volume a closed, consistently oriented mesh encloses follows from the divergence theorem
// (signed_volume, coupling/mesh/mass_properties.h). Checked on a resting lattice box of liquid,
// as the scene builder places fluid (centres at (i + 1/2) h), and on a ball of lattice
// particles; the mesh must be closed (check_closed, coupling/mesh/closed_mesh.h) with normals
// pointing out, and be the same at every call.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mass_properties.h"
#include "framework/output/liquid_surface.h"
#include "framework/particles/particles.h"

namespace upf {
namespace {

constexpr double kH = 0.02;

std::vector<Eigen::Vector3d> lattice_box(int nx, int ny, int nz, double h) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) p.emplace_back((i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h);
  return p;
}

// Lattice particles whose centres lie within `radius` of `center`.
std::vector<Eigen::Vector3d> lattice_ball(const Eigen::Vector3d& center, double radius, double h) {
  std::vector<Eigen::Vector3d> p;
  const int n = int(std::ceil(radius / h)) + 1;
  for (int i = -n; i < n; ++i)
    for (int j = -n; j < n; ++j)
      for (int k = -n; k < n; ++k) {
        const Eigen::Vector3d x((i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h);
        if (x.norm() < radius) p.push_back(center + x);
      }
  return p;
}

TriangleMesh as_triangle_mesh(const MeshPiece& piece) {
  return TriangleMesh{piece.vertices, piece.triangles, "liquid surface"};
}

// Closed and oriented outwards; returns the enclosed volume.
double expect_closed_outward(const MeshPiece& piece) {
  const TriangleMesh mesh = as_triangle_mesh(piece);
  const ClosedMeshReport report = check_closed(mesh);
  EXPECT_EQ(report.boundary_edges, 0u);
  EXPECT_EQ(report.non_manifold_edges, 0u);
  EXPECT_EQ(report.misoriented_edges, 0u);
  const double volume = signed_volume(mesh);
  EXPECT_GT(volume, 0) << "normals point inwards";
  return volume;
}

// Both surfacing methods (liquid_surface.h) must hold the volume.
class EachMethod : public testing::TestWithParam<SurfaceMethod> {
 protected:
  static LiquidSurfaceOptions options() {
    LiquidSurfaceOptions o;
    o.method = GetParam();
    return o;
  }
};

INSTANTIATE_TEST_SUITE_P(LiquidSurface, EachMethod,
                         testing::Values(SurfaceMethod::anisotropic, SurfaceMethod::spheres),
                         [](const testing::TestParamInfo<SurfaceMethod>& param) {
                           return param.param == SurfaceMethod::spheres ? "Spheres" : "Anisotropic";
                         });

TEST_P(EachMethod, RestingBoxIsClosedAndEnclosesTheLiquidVolume) {
  const int nx = 20, ny = 12, nz = 16;
  const auto particles = lattice_box(nx, ny, nz, kH);
  const MeshPiece mesh = liquid_surface_mesh(particles, kH, options());
  ASSERT_FALSE(mesh.triangles.empty());
  const double volume = expect_closed_outward(mesh);
  const double liquid = double(particles.size()) * kH * kH * kH;
  std::printf(
      "box of %zu particles: %zu vertices, %zu triangles, volume %.6g m^3 vs N h^3 %.6g "
      "(%+.2f %%)\n",
      particles.size(), mesh.vertices.size(), mesh.triangles.size(), volume, liquid,
      100 * (volume / liquid - 1));
  EXPECT_NEAR(volume / liquid, 1.0, 0.03);

  // The faces lie h/2 beyond the outermost centres, i.e. on the block's bounds [0, n h].
  const Eigen::AlignedBox3d box = bounding_box(as_triangle_mesh(mesh));
  const Eigen::Vector3d size(nx * kH, ny * kH, nz * kH);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(box.min()[a], 0.0, 0.1 * kH) << "axis " << a;
    EXPECT_NEAR(box.max()[a], size[a], 0.1 * kH) << "axis " << a;
  }

  // Outward locally too: triangles on the top face point up.
  const TriangleMesh tm = as_triangle_mesh(mesh);
  int top = 0, down = 0;
  for (std::size_t t = 0; t < tm.triangles.size(); ++t) {
    const auto& tri = tm.triangles[t];
    bool on_top = true;
    for (auto v : tri) on_top = on_top && tm.vertices[v].y() > size.y() - 0.1 * kH;
    if (!on_top) continue;
    ++top;
    if (triangle_area_vector(tm, t).y() <= 0) ++down;
  }
  EXPECT_GT(top, 0);
  EXPECT_EQ(down, 0) << "of " << top << " triangles on the top face";
}

TEST_P(EachMethod, BallOfParticlesEnclosesTheLiquidVolume) {
  // Lattice particles within 5h of the centre. At this size the lattice count N h^3 is 5 % above
  // (4/3) pi (5h)^3, so the reference is N h^3 and the sphere of that volume, radius r_eq.
  const Eigen::Vector3d center(0.31, -0.27, 0.05);
  const auto particles = lattice_ball(center, 5 * kH, kH);
  const MeshPiece mesh = liquid_surface_mesh(particles, kH, options());
  const double volume = expect_closed_outward(mesh);
  const double liquid = double(particles.size()) * kH * kH * kH;
  const double r_eq = std::cbrt(liquid / (4.0 / 3.0 * std::numbers::pi));
  std::printf(
      "ball of %zu particles: %zu vertices, %zu triangles, volume %.6g m^3 vs N h^3 %.6g "
      "(%+.2f %%)\n",
      particles.size(), mesh.vertices.size(), mesh.triangles.size(), volume, liquid,
      100 * (volume / liquid - 1));
  EXPECT_NEAR(volume / liquid, 1.0, 0.05);
  // Round: every vertex within h/2 of the sphere of the liquid's volume.
  double worst = 0;
  for (const auto& v : mesh.vertices) worst = std::max(worst, std::abs((v - center).norm() - r_eq));
  EXPECT_LT(worst, 0.5 * kH);
}

TEST(LiquidSurface, SeparateDropsGiveSeparateClosedSurfaces) {
  // Two balls far apart: each one closed, the volumes add up.
  auto a = lattice_ball(Eigen::Vector3d(0, 0, 0), 3 * kH, kH);
  const auto b = lattice_ball(Eigen::Vector3d(1, 0, 0), 3 * kH, kH);
  const double va = expect_closed_outward(liquid_surface_mesh(a, kH));
  a.insert(a.end(), b.begin(), b.end());
  const double both = expect_closed_outward(liquid_surface_mesh(a, kH));
  EXPECT_NEAR(both, 2 * va, 1e-4 * va);  // float vertices: rounding differs at x = 1
}

TEST(LiquidSurface, EmptyInputGivesEmptyMesh) {
  const MeshPiece mesh = liquid_surface_mesh(std::vector<Eigen::Vector3d>{}, kH);
  EXPECT_TRUE(mesh.vertices.empty());
  EXPECT_TRUE(mesh.triangles.empty());
  EXPECT_TRUE(liquid_surface_mesh(Particles{}, kH).triangles.empty());
}

TEST_P(EachMethod, SameInputGivesTheSameMeshWhateverTheThreads) {
  auto particles = lattice_box(14, 9, 11, kH);
  // Some irregularity, so ties and ordering matter.
  for (std::size_t i = 0; i < particles.size(); ++i)
    particles[i] += 0.3 * kH *
                    Eigen::Vector3d(std::sin(1.3 * double(i)), std::cos(0.7 * double(i)),
                                    std::sin(0.37 * double(i) + 1));
  const MeshPiece first = liquid_surface_mesh(particles, kH, options());
  const MeshPiece second = liquid_surface_mesh(particles, kH, options());
  LiquidSurfaceOptions one_thread = options();
  one_thread.threads = 1;
  const MeshPiece serial = liquid_surface_mesh(particles, kH, one_thread);
  ASSERT_FALSE(first.triangles.empty());
  EXPECT_TRUE(first.vertices == second.vertices);
  EXPECT_TRUE(first.triangles == second.triangles);
  EXPECT_TRUE(first.vertices == serial.vertices);
  EXPECT_TRUE(first.triangles == serial.triangles);
}

TEST(LiquidSurface, OnlyLiquidParticlesAreMeshed) {
  Particles particles;
  for (const auto& x : lattice_box(6, 6, 6, kH))
    particles.add({Real(x.x()), Real(x.y()), Real(x.z())}, {}, 1, ParticleType::Liquid, 0);
  const MeshPiece liquid_only = liquid_surface_mesh(particles, kH);
  // A wall of frozen particles beside the liquid changes nothing.
  for (const auto& x : lattice_box(1, 6, 6, kH))
    particles.add({Real(x.x() - 2 * kH), Real(x.y()), Real(x.z())}, {}, 1, ParticleType::Frozen, 1);
  const MeshPiece with_wall = liquid_surface_mesh(particles, kH);
  ASSERT_FALSE(liquid_only.triangles.empty());
  EXPECT_TRUE(liquid_only.vertices == with_wall.vertices);
  EXPECT_TRUE(liquid_only.triangles == with_wall.triangles);
}

TEST(LiquidSurface, RejectsBadSpacingOptionsAndPositions) {
  const std::vector<Eigen::Vector3d> one{Eigen::Vector3d::Zero()};
  EXPECT_THROW(liquid_surface_mesh(one, 0.0), std::invalid_argument);
  EXPECT_THROW(liquid_surface_mesh(one, std::nan("")), std::invalid_argument);
  LiquidSurfaceOptions o;
  o.voxel_factor = 2;  // R = 1 voxel: OpenVDB would drop every sphere
  EXPECT_THROW(liquid_surface_mesh(one, kH, o), std::invalid_argument);
  o = {};
  o.radius_factor = 0.5;
  EXPECT_THROW(liquid_surface_mesh(one, kH, o), std::invalid_argument);
  o = {};
  o.smoothing_iterations = -1;
  EXPECT_THROW(liquid_surface_mesh(one, kH, o), std::invalid_argument);
  for (double bad_radius : {0.5, 11.0, std::nan("")}) {
    o = {};
    o.anisotropy.kernel_radius = bad_radius;
    EXPECT_THROW(liquid_surface_mesh(one, kH, o), std::invalid_argument);
  }
  o = {};
  o.anisotropy.level = 1.0;
  EXPECT_THROW(liquid_surface_mesh(one, kH, o), std::invalid_argument);
  o = {};
  o.anisotropy.max_stretch = 0.5;
  EXPECT_THROW(liquid_surface_mesh(one, kH, o), std::invalid_argument);
  const std::vector<Eigen::Vector3d> bad{Eigen::Vector3d(0, std::nan(""), 0)};
  EXPECT_THROW(liquid_surface_mesh(bad, kH), std::invalid_argument);
}

}  // namespace
}  // namespace upf
