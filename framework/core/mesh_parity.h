// "Is this point inside the closed mesh?" by ray parity, as plain arrays that a device can hold:
// a ray from the point along +x crosses the surface an odd number of times exactly when the point
// is inside (the Jordan-Brouwer separation theorem; each crossing is the point-in-polygon test of
// a triangle's projection, E. Haines 1994, "Point in polygon strategies", Graphics Gems IV).
//
// Triangles are binned by their projections on the (y, z) plane, so a query tests only its own
// bin's triangles. The query ray is shifted by a tiny, irrational fraction of a bin in y and z,
// so points of a lattice that lines up with mesh edges or vertices (a box on the particle grid)
// do not hit an edge and count it twice. MeshInsideTest (coupling/mesh) builds the data; the
// host and the device pipeline run the same view.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "framework/core/vec3d.h"

namespace upf {

// A view's arrays, on the host.
struct MeshParityData {
  std::vector<Vec3d> vertices;
  std::vector<std::uint32_t> triangles;    // three vertex indices each
  std::vector<std::uint32_t> bin_offsets;  // CSR over bins y + bins_y * z
  std::vector<std::uint32_t> bin_triangles;
  Vec3d box_min, box_max;
  double bin_size = 1;
  int bins_y = 1, bins_z = 1;
};

struct MeshParityView {
  const Vec3d* vertices = nullptr;
  const std::uint32_t* triangles = nullptr;
  const std::uint32_t* bin_offsets = nullptr;
  const std::uint32_t* bin_triangles = nullptr;
  Vec3d box_min, box_max;
  double bin_size = 1;
  int bins_y = 1, bins_z = 1;

  // Shift of every query ray, in bins: irrational, so no lattice of points lines up with it.
  static constexpr double kShiftY = 0.6180339887e-6;
  static constexpr double kShiftZ = 0.4142135623e-6;

  UPF_HD static int clamp_bin(double coordinate, double origin, double size, int count) {
    const double b = floor((coordinate - origin) / size);
    if (!(b > 0)) return 0;
    return b > double(count - 1) ? count - 1 : int(b);
  }

  UPF_HD bool contains(const Vec3d& p) const {
    if (p.x < box_min.x || p.y < box_min.y || p.z < box_min.z || p.x > box_max.x ||
        p.y > box_max.y || p.z > box_max.z)
      return false;
    const double py = p.y + kShiftY * bin_size;
    const double pz = p.z + kShiftZ * bin_size;
    const int by = clamp_bin(py, box_min.y, bin_size, bins_y);
    const int bz = clamp_bin(pz, box_min.z, bin_size, bins_z);
    const std::uint32_t bin = std::uint32_t(by) + std::uint32_t(bins_y) * std::uint32_t(bz);
    bool inside = false;
    for (std::uint32_t k = bin_offsets[bin]; k < bin_offsets[bin + 1]; ++k) {
      const std::uint32_t t = bin_triangles[k];
      const Vec3d a = vertices[triangles[3 * t]];
      const Vec3d b = vertices[triangles[3 * t + 1]];
      const Vec3d c = vertices[triangles[3 * t + 2]];
      // Barycentric coordinates of (py, pz) in the triangle's (y, z) projection.
      const double d = (b.y - a.y) * (c.z - a.z) - (c.y - a.y) * (b.z - a.z);
      if (d == 0) continue;  // edge-on to the ray: a neighbour counts the crossing
      const double u = ((py - a.y) * (c.z - a.z) - (c.y - a.y) * (pz - a.z)) / d;
      const double v = ((b.y - a.y) * (pz - a.z) - (py - a.y) * (b.z - a.z)) / d;
      if (u < 0 || v < 0 || u + v > 1) continue;
      const double x = a.x + u * (b.x - a.x) + v * (c.x - a.x);
      if (x > p.x) inside = !inside;
    }
    return inside;
  }
};

// The view of `data`'s arrays where they are (host vectors here; a device copies them first).
inline MeshParityView host_view(const MeshParityData& data) {
  return {data.vertices.data(),
          data.triangles.data(),
          data.bin_offsets.data(),
          data.bin_triangles.data(),
          data.box_min,
          data.box_max,
          data.bin_size,
          data.bins_y,
          data.bins_z};
}

}  // namespace upf
