// "Is this point inside the closed mesh?": the ray-parity test of framework/core/mesh_parity.h,
// built from a triangle mesh (bins of the triangles' (y, z) projections), so the host and the
// device pipeline (which copies data()) answer alike.
#pragma once

#include <Eigen/Core>

#include "coupling/mesh/triangle_mesh.h"
#include "framework/core/mesh_parity.h"

namespace upf {

class MeshInsideTest {
 public:
  // `bin_size`: edge of the (y, z) bins, m; the particle spacing suits.
  MeshInsideTest(const TriangleMesh& mesh, double bin_size);

  bool contains(const Eigen::Vector3d& point) const {
    return host_view(data_).contains({point.x(), point.y(), point.z()});
  }
  const MeshParityData& data() const { return data_; }

 private:
  MeshParityData data_;
};

}  // namespace upf
