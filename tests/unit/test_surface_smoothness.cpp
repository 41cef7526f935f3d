// How smooth the liquid surface mesh is (framework/output/liquid_surface.h, anisotropic kernels
// of Yu & Turk 2013, "Reconstructing surfaces of particle-based fluids using anisotropic
// kernels", ACM TOG 32(1)). References:
//  - a resting pool's free surface is a plane (hydrostatics), at the liquid's volume over the
//    pool's area: h/2 above the top particle centres of a lattice block. Its particles are not
//    on a lattice after settling: in upf's hydrostatic tank (samples/hydrostatic_tank.json,
//    PCISPH, 2 cm) the top layer's heights have a standard deviation of 0.06 h at t = 1 s, and
//    a uniform jitter of +-0.1 h (standard deviation 0.058 h) stands for that here;
//  - a sheet one particle thick has two faces of the sheet's area (Yu & Turk's Fig. 1: isotropic
//    kernels break thin sheets into blobs);
//  - a lone particle stands for a volume h^3 (mass / rho0).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mass_properties.h"
#include "framework/output/anisotropic_kernels.h"
#include "framework/output/liquid_surface.h"

namespace upf {
namespace {

constexpr double kH = 0.02;

// Uniform numbers in [-1, 1) from a 64-bit linear congruential generator (Knuth's MMIX
// constants): the same on every platform, unlike the standard distributions.
class Jitter {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state_ >> 11) * 0x1.0p-53 * 2 - 1;
  }

 private:
  std::uint64_t state_ = 1;
};

// A pool nx * ny * nz lattice spacings, every centre moved by up to `jitter` h on each axis.
std::vector<Eigen::Vector3d> jittered_pool(int nx, int ny, int nz, double jitter) {
  Jitter random;
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const Eigen::Vector3d lattice((i + 0.5) * kH, (j + 0.5) * kH, (k + 0.5) * kH);
        const Eigen::Vector3d offset(random.next(), random.next(), random.next());
        p.push_back(lattice + jitter * kH * offset);
      }
  return p;
}

struct Flatness {
  double mean = 0;              // mean height of the top face's vertices
  double spread = 0;            // largest minus smallest
  double rms_tilt_degrees = 0;  // of the top face's triangle normals from vertical
  int vertices = 0;
};

// The vertices of the top face at least `margin` inside the pool's sides (the rounded edges
// left out), and the triangles whose vertices are all such.
Flatness top_face(const MeshPiece& mesh, double top, double width_x, double width_z,
                  double margin) {
  const auto on_top = [&](const Eigen::Vector3d& v) {
    return v.y() > top - 1.5 * kH && v.x() > margin && v.x() < width_x - margin && v.z() > margin &&
           v.z() < width_z - margin;
  };
  Flatness f;
  double lo = 1e30;
  double hi = -1e30;
  for (const auto& v : mesh.vertices)
    if (on_top(v)) {
      ++f.vertices;
      f.mean += v.y();
      lo = std::min(lo, v.y());
      hi = std::max(hi, v.y());
    }
  f.mean /= std::max(f.vertices, 1);
  f.spread = hi - lo;
  double sum_tilt2 = 0;
  int faces = 0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    if (!(on_top(a) && on_top(b) && on_top(c))) continue;
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    const double tilt = std::acos(std::clamp(n.y(), -1.0, 1.0)) * 180 / 3.141592653589793;
    sum_tilt2 += tilt * tilt;
    ++faces;
  }
  f.rms_tilt_degrees = std::sqrt(sum_tilt2 / std::max(faces, 1));
  return f;
}

double enclosed_volume(const MeshPiece& mesh) {
  return signed_volume(TriangleMesh{mesh.vertices, mesh.triangles, "liquid surface"});
}

double area(const MeshPiece& mesh) {
  double sum = 0;
  for (const auto& t : mesh.triangles)
    sum += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                     .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                     .norm();
  return sum;
}

TEST(SurfaceSmoothness, ARestingPoolIsFlatWithinAFifthOfASpacing) {
  const int nx = 24, ny = 10, nz = 24;
  const auto pool = jittered_pool(nx, ny, nz, 0.1);
  const double top = ny * kH;  // the top centres' plane plus h/2
  const Flatness smooth = top_face(liquid_surface_mesh(pool, kH), top, nx * kH, nz * kH, 3 * kH);
  LiquidSurfaceOptions spheres;
  spheres.method = SurfaceMethod::spheres;
  const Flatness bumpy =
      top_face(liquid_surface_mesh(pool, kH, spheres), top, nx * kH, nz * kH, 3 * kH);
  std::printf(
      "top face: anisotropic mean %+.3f h, spread %.3f h, normals %.2f deg rms (%d vertices); "
      "spheres mean %+.3f h, spread %.3f h, normals %.2f deg rms\n",
      (smooth.mean - top) / kH, smooth.spread / kH, smooth.rms_tilt_degrees, smooth.vertices,
      (bumpy.mean - top) / kH, bumpy.spread / kH, bumpy.rms_tilt_degrees);
  ASSERT_GT(smooth.vertices, 500);
  EXPECT_LT(smooth.spread, 0.2 * kH);
  EXPECT_NEAR(smooth.mean, top, 0.1 * kH);
  // A bump pattern shows in the shading, through the normals.
  EXPECT_LT(smooth.rms_tilt_degrees, 2.0);
}

TEST(SurfaceSmoothness, AThinSheetStaysOneSheet) {
  // One layer of 20 x 20 particles: a sheet h thick with two faces of (20 h)^2 each.
  std::vector<Eigen::Vector3d> sheet;
  for (int i = 0; i < 20; ++i)
    for (int k = 0; k < 20; ++k) sheet.emplace_back((i + 0.5) * kH, 0.5 * kH, (k + 0.5) * kH);
  const MeshPiece mesh = liquid_surface_mesh(sheet, kH);
  const ClosedMeshReport report = check_closed(TriangleMesh{mesh.vertices, mesh.triangles, "s"});
  EXPECT_EQ(report.boundary_edges, 0u);
  const double faces = 2 * (20 * kH) * (20 * kH);
  const double volume = enclosed_volume(mesh) / (400 * kH * kH * kH);
  std::printf("sheet: area %.3f of two faces, volume %.3f of N h^3\n", area(mesh) / faces, volume);
  // Not broken into blobs (which would add area) nor holed (which would lose it).
  EXPECT_NEAR(area(mesh) / faces, 1.0, 0.15);
  EXPECT_GT(volume, 0.6);
  EXPECT_LT(volume, 1.1);
}

TEST(AnisotropicKernels, RoundInsideFlatAtTheSurface) {
  std::vector<Eigen::Vector3d> block;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 12; ++k) block.emplace_back(i * kH, j * kH, k * kH);
  const AnisotropyParameters p;
  const auto kernels = anisotropic_kernels(block, kH, p);
  const auto at = [&](int i, int j, int k) { return kernels[std::size_t((i * 12 + j) * 12 + k)]; };
  // Deep inside: a sphere of radius kernel_radius h (G = I / (kernel_radius h)).
  const AnisotropicKernel inside = at(6, 6, 6);
  const Eigen::Matrix3d round = Eigen::Matrix3d::Identity() / (p.kernel_radius * kH);
  EXPECT_LT((inside.g - round).norm(), 1e-6 * round.norm());
  // On the top face: shortest across the face (G largest along y), wider along it, and the
  // same volume as the round kernel (det G unchanged).
  const AnisotropicKernel top = at(6, 11, 6);
  const Eigen::Vector3d axis_lengths(1 / (top.g * Eigen::Vector3d::UnitX()).norm(),
                                     1 / (top.g * Eigen::Vector3d::UnitY()).norm(),
                                     1 / (top.g * Eigen::Vector3d::UnitZ()).norm());
  std::printf("top kernel axes / round: %.3f %.3f %.3f\n",
              axis_lengths.x() / (p.kernel_radius * kH), axis_lengths.y() / (p.kernel_radius * kH),
              axis_lengths.z() / (p.kernel_radius * kH));
  EXPECT_LT(axis_lengths.y(), 0.8 * axis_lengths.x());
  EXPECT_NEAR(axis_lengths.x(), axis_lengths.z(), 1e-6 * axis_lengths.x());
  EXPECT_NEAR(top.g.determinant(), round.determinant(), 1e-6 * round.determinant());
  // A lone particle: a round kernel sparse_scale times as wide.
  const auto lone = anisotropic_kernels({Eigen::Vector3d(1, 2, 3)}, kH, p);
  EXPECT_LT((lone[0].g - round / p.sparse_scale).norm(), 1e-9 * round.norm());
}

}  // namespace
}  // namespace upf
