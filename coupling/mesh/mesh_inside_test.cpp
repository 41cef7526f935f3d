#include "coupling/mesh/mesh_inside_test.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace upf {

namespace {

// Shift of every query ray, in bins: irrational, so no lattice of points lines up with it.
constexpr double kShiftY = 0.6180339887e-6;
constexpr double kShiftZ = 0.4142135623e-6;

int clamp_bin(double coordinate, double origin, double size, int count) {
  const double b = std::floor((coordinate - origin) / size);
  return int(std::clamp(b, 0.0, double(count - 1)));
}

}  // namespace

MeshInsideTest::MeshInsideTest(TriangleMesh mesh_in, double bin_size)
    : mesh_(std::move(mesh_in)), box_(bounding_box(mesh_)), bin_size_(bin_size) {
  const TriangleMesh& mesh = mesh_;
  const Eigen::Vector3d extent = box_.sizes();
  // At most 1024 bins a side: a huge mesh at a tiny spacing gets coarser bins, not a huge table.
  bin_size_ = std::max({bin_size_, extent.y() / 1024, extent.z() / 1024, 1e-12});
  bins_y_ = std::max(1, int(std::ceil(extent.y() / bin_size_)));
  bins_z_ = std::max(1, int(std::ceil(extent.z() / bin_size_)));
  bins_.resize(std::size_t(bins_y_) * std::size_t(bins_z_));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Eigen::AlignedBox3d tb;
    for (std::uint32_t v : mesh.triangles[t]) tb.extend(mesh.vertices[v]);
    const int y0 = clamp_bin(tb.min().y(), box_.min().y(), bin_size_, bins_y_);
    const int y1 = clamp_bin(tb.max().y(), box_.min().y(), bin_size_, bins_y_);
    const int z0 = clamp_bin(tb.min().z(), box_.min().z(), bin_size_, bins_z_);
    const int z1 = clamp_bin(tb.max().z(), box_.min().z(), bin_size_, bins_z_);
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        bins_[std::size_t(y) + std::size_t(bins_y_) * std::size_t(z)].push_back(std::uint32_t(t));
  }
}

bool MeshInsideTest::contains(const Eigen::Vector3d& point) const {
  if (!box_.contains(point)) return false;
  const double py = point.y() + kShiftY * bin_size_;
  const double pz = point.z() + kShiftZ * bin_size_;
  const int by = clamp_bin(py, box_.min().y(), bin_size_, bins_y_);
  const int bz = clamp_bin(pz, box_.min().z(), bin_size_, bins_z_);
  bool inside = false;
  for (std::uint32_t t : bins_[std::size_t(by) + std::size_t(bins_y_) * std::size_t(bz)]) {
    const auto& tri = mesh_.triangles[t];
    const Eigen::Vector3d& a = mesh_.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh_.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh_.vertices[tri[2]];
    // Barycentric coordinates of (py, pz) in the triangle's (y, z) projection.
    const double d = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
    if (d == 0) continue;  // edge-on to the ray: a neighbour counts the crossing
    const double u = ((py - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (pz - a.z())) / d;
    const double v = ((b.y() - a.y()) * (pz - a.z()) - (py - a.y()) * (b.z() - a.z())) / d;
    if (u < 0 || v < 0 || u + v > 1) continue;
    const double x = a.x() + u * (b.x() - a.x()) + v * (c.x() - a.x());
    if (x > point.x()) inside = !inside;
  }
  return inside;
}

}  // namespace upf
