#include "coupling/mesh/mesh_inside_test.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace upf {

MeshInsideTest::MeshInsideTest(const TriangleMesh& mesh, double bin_size) {
  const Eigen::AlignedBox3d box = bounding_box(mesh);
  const Eigen::Vector3d extent = box.sizes();
  MeshParityData& d = data_;
  d.box_min = {box.min().x(), box.min().y(), box.min().z()};
  d.box_max = {box.max().x(), box.max().y(), box.max().z()};
  // At most 1024 bins a side: a huge mesh at a tiny spacing gets coarser bins, not a huge table.
  d.bin_size = std::max({bin_size, extent.y() / 1024, extent.z() / 1024, 1e-12});
  d.bins_y = std::max(1, int(std::ceil(extent.y() / d.bin_size)));
  d.bins_z = std::max(1, int(std::ceil(extent.z() / d.bin_size)));
  for (const auto& v : mesh.vertices) d.vertices.push_back({v.x(), v.y(), v.z()});
  for (const auto& t : mesh.triangles) d.triangles.insert(d.triangles.end(), t.begin(), t.end());

  std::vector<std::vector<std::uint32_t>> bins(std::size_t(d.bins_y) * std::size_t(d.bins_z));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Eigen::AlignedBox3d tb;
    for (std::uint32_t v : mesh.triangles[t]) tb.extend(mesh.vertices[v]);
    const int y0 = MeshParityView::clamp_bin(tb.min().y(), d.box_min.y, d.bin_size, d.bins_y);
    const int y1 = MeshParityView::clamp_bin(tb.max().y(), d.box_min.y, d.bin_size, d.bins_y);
    const int z0 = MeshParityView::clamp_bin(tb.min().z(), d.box_min.z, d.bin_size, d.bins_z);
    const int z1 = MeshParityView::clamp_bin(tb.max().z(), d.box_min.z, d.bin_size, d.bins_z);
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        bins[std::size_t(y) + std::size_t(d.bins_y) * std::size_t(z)].push_back(std::uint32_t(t));
  }
  d.bin_offsets.push_back(0);
  for (const auto& bin : bins) {
    d.bin_triangles.insert(d.bin_triangles.end(), bin.begin(), bin.end());
    d.bin_offsets.push_back(std::uint32_t(d.bin_triangles.size()));
  }
}

}  // namespace upf
