// Surface sampling (dart throwing, Cook 1986 / Corsini et al. 2012, then gap filling by
// subdivision, Ebeida et al. 2011) checked against its two promises by brute force, independent
// of the sampler's grid:
//   coverage: the largest distance from a surface point to its nearest sample is <= h/2, so no
//             sample-free disk on the surface is wider than h. Measured over 20000 area-weighted
//             random surface points plus every vertex and edge midpoint (where gaps hide);
//   spacing:  the smallest distance between two samples is >= 0.45 h ("not much closer than
//             h/2").
// On a sphere, a non-convex torus and a non-convex block with sharp edges; also determinism,
// normals, and bad spacings. The measured figures are printed for docs/meshes.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "coupling/mesh/mesh_loader.h"
#include "coupling/sampling/surface_sampler.h"
#include "test_mesh_support.h"

namespace upf {
namespace {

using mesh_test::asset;
using mesh_test::input_error_text;

// Where coverage is checked: random points, area-weighted, then vertices and edge midpoints.
std::vector<Eigen::Vector3d> probe_points(const TriangleMesh& mesh, int random_count) {
  std::vector<double> cumulative_area;
  double total = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    cumulative_area.push_back(total += triangle_area(mesh, t));
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Eigen::Vector3d> probes;
  for (int n = 0; n < random_count; ++n) {
    const auto t = std::size_t(
        std::lower_bound(cumulative_area.begin(), cumulative_area.end(), unit(rng) * total) -
        cumulative_area.begin());
    const auto& tri = mesh.triangles[std::min(t, mesh.triangles.size() - 1)];
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    probes.push_back(a + u * (mesh.vertices[tri[1]] - a) + v * (mesh.vertices[tri[2]] - a));
  }
  for (const auto& v : mesh.vertices) probes.push_back(v);
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      probes.push_back((mesh.vertices[tri[k]] + mesh.vertices[tri[(k + 1) % 3]]) / 2);
  return probes;
}

struct Quality {
  double largest_gap = 0;  // max over probes of the distance to the nearest sample, in h
  double closest_pair = std::numeric_limits<double>::infinity();  // in h
};

// Nearest-sample distances by a sweep over the samples sorted by x: exact, and independent of
// the sampler's grid.
class NearestSample {
 public:
  explicit NearestSample(std::vector<Eigen::Vector3d> samples) : sorted_(std::move(samples)) {
    std::sort(sorted_.begin(), sorted_.end(),
              [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.x() < b.x(); });
  }
  // Distance from p to the nearest sample, ignoring the sample at index `skip` of the sorted
  // order (pass sorted().size() to skip none).
  double distance(const Eigen::Vector3d& p, std::size_t skip) const {
    const auto start =
        std::lower_bound(sorted_.begin(), sorted_.end(), p.x(),
                         [](const Eigen::Vector3d& s, double x) { return s.x() < x; });
    double best = std::numeric_limits<double>::infinity();
    for (auto it = start; it != sorted_.end() && it->x() - p.x() < best; ++it)
      if (std::size_t(it - sorted_.begin()) != skip) best = std::min(best, (*it - p).norm());
    for (auto it = start; it != sorted_.begin() && p.x() - (it - 1)->x() < best; --it)
      if (std::size_t(it - 1 - sorted_.begin()) != skip)
        best = std::min(best, (*(it - 1) - p).norm());
    return best;
  }
  const std::vector<Eigen::Vector3d>& sorted() const { return sorted_; }

 private:
  std::vector<Eigen::Vector3d> sorted_;
};

Quality measure(const TriangleMesh& mesh, const SurfaceSamples& samples, double h) {
  const NearestSample nearest(samples.positions);
  const std::size_t none = nearest.sorted().size();
  Quality q;
  for (const auto& p : probe_points(mesh, 20000))
    q.largest_gap = std::max(q.largest_gap, nearest.distance(p, none) / h);
  for (std::size_t i = 0; i < nearest.sorted().size(); ++i)
    q.closest_pair = std::min(q.closest_pair, nearest.distance(nearest.sorted()[i], i) / h);
  return q;
}

void expect_promises_kept(const char* name, const TriangleMesh& mesh, double h,
                          SurfaceSamplingOptions options = {}) {
  options.spacing = h;
  const SurfaceSamples samples = sample_surface(mesh, options, "");
  const Quality q = measure(mesh, samples, h);
  const double per_area = double(samples.positions.size()) * h * h / surface_area(mesh);
  std::printf(
      "[ %-7s ] h = %g: %zu samples (%.2f per h^2), largest gap %.4f h, closest pair "
      "%.4f h\n",
      name, h, samples.positions.size(), per_area, q.largest_gap, q.closest_pair);
  EXPECT_LE(q.largest_gap, kSampleCoverageRadius * (1 + 1e-9)) << name;
  EXPECT_GE(q.closest_pair, kSampleMinDistance * (1 - 1e-9)) << name;
  ASSERT_EQ(samples.normals.size(), samples.positions.size());
  ASSERT_EQ(samples.triangles.size(), samples.positions.size());
  for (std::size_t i = 0; i < samples.positions.size(); ++i) {
    const auto& tri = mesh.triangles[samples.triangles[i]];
    EXPECT_NEAR(samples.normals[i].norm(), 1.0, 1e-12);
    // On its triangle's plane, with the triangle's normal.
    EXPECT_NEAR(samples.normals[i].dot(samples.positions[i] - mesh.vertices[tri[0]]), 0, 1e-12);
    EXPECT_TRUE(samples.normals[i].isApprox(
        triangle_area_vector(mesh, samples.triangles[i]).normalized(), 1e-12));
  }
}

TEST(MeshSampling, SphereCoveredAndSpaced) {
  expect_promises_kept("sphere", load_mesh(asset("icosphere.ply")), 0.1);
}

TEST(MeshSampling, NonConvexTorusCoveredAndSpaced) {
  expect_promises_kept("torus", load_mesh(asset("torus.glb")), 0.05);
}

TEST(MeshSampling, SharpEdgedBlockCoveredAndSpaced) {
  MeshTransform in_mm;
  in_mm.unit = 0.001;
  expect_promises_kept("l_block", load_mesh(asset("l_block_mm.stl"), in_mm), 0.002);
}

TEST(MeshSampling, SpacingLargerThanTheMeshStillCovers) {
  expect_promises_kept("coarse", load_mesh(asset("unit_box.obj")), 0.9);
}

TEST(MeshSampling, PromisesHoldForAnyTuning) {
  const TriangleMesh torus = load_mesh(asset("torus.glb"));
  expect_promises_kept("no darts", torus, 0.08, {.darts_per_disk = 0});
  expect_promises_kept("sparse", torus, 0.08, {.dart_radius = 1.1, .darts_per_disk = 2});
  expect_promises_kept("tight", torus, 0.08, {.dart_radius = 0.45, .darts_per_disk = 30});
}

TEST(MeshSampling, NormalsOfAClosedMeshPointOutwards) {
  const SurfaceSamples samples =
      sample_surface(load_mesh(asset("icosphere.ply")), {.spacing = 0.1}, "");
  for (std::size_t i = 0; i < samples.positions.size(); ++i)
    EXPECT_GT(samples.normals[i].dot(samples.positions[i].normalized()), 0.99);
}

TEST(MeshSampling, SameMeshSameSamples) {
  const TriangleMesh mesh = load_mesh(asset("torus.glb"));
  const SurfaceSamples first = sample_surface(mesh, {.spacing = 0.05}, "");
  const SurfaceSamples second = sample_surface(mesh, {.spacing = 0.05}, "");
  ASSERT_EQ(first.positions.size(), second.positions.size());
  for (std::size_t i = 0; i < first.positions.size(); ++i) {
    EXPECT_EQ(first.positions[i], second.positions[i]) << i;  // bitwise
    EXPECT_EQ(first.triangles[i], second.triangles[i]) << i;
  }
  const SurfaceSamples other_seed = sample_surface(mesh, {.spacing = 0.05, .seed = 2}, "");
  EXPECT_NE(other_seed.positions.front(), first.positions.front());
}

TEST(MeshSampling, BadSpacingNamesTheFile) {
  const TriangleMesh mesh = load_mesh(asset("unit_box.obj"));
  for (const double h : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    const std::string text = input_error_text([&] { sample_surface(mesh, {.spacing = h}, "/b"); });
    EXPECT_NE(text.find("/b: mesh file '" + mesh.source + "': the sampling spacing must be"),
              std::string::npos)
        << text;
  }
  const std::string text = input_error_text([&] { sample_surface(mesh, {.spacing = 1e-6}, "/b"); });
  EXPECT_NE(text.find("is too fine for this mesh"), std::string::npos) << text;
}

}  // namespace
}  // namespace upf
