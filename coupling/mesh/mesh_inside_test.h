// "Is this point inside the closed mesh?" by ray parity: a ray from the point along +x crosses
// the surface an odd number of times exactly when the point is inside (the Jordan-Brouwer
// separation theorem; the crossing test is the point-in-polygon test of each triangle's
// projection, as in E. Haines 1994, "Point in polygon strategies", Graphics Gems IV).
//
// Triangles are binned by their projections on the (y, z) plane, so a query tests only the
// triangles of its own bin. The query ray is shifted by a tiny, irrational fraction of a bin in
// y and z, so points of a lattice that lines up with mesh edges or vertices (a box on the
// particle grid) do not hit an edge and count it twice.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "coupling/mesh/triangle_mesh.h"

namespace upf {

class MeshInsideTest {
 public:
  // `bin_size`: edge of the (y, z) bins, m; the particle spacing suits. Keeps a copy of the mesh.
  MeshInsideTest(TriangleMesh mesh, double bin_size);

  bool contains(const Eigen::Vector3d& point) const;

 private:
  TriangleMesh mesh_;
  Eigen::AlignedBox3d box_;
  double bin_size_;
  int bins_y_ = 1, bins_z_ = 1;
  std::vector<std::vector<std::uint32_t>> bins_;  // triangle indices, bin y + bins_y * z
};

}  // namespace upf
