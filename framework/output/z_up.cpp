#include "framework/output/z_up.h"

namespace upf {

void turn_to_z_up(Particles& p) {
  for (Vec3& x : p.position) x = to_z_up(x);
  for (Vec3& v : p.velocity) v = to_z_up(v);
  for (const auto& [name, field] : p.vector_fields())
    for (Vec3& v : *p.find_vector(name)) v = to_z_up(v);
}

void turn_to_z_up(MeshPiece& mesh) {
  for (Eigen::Vector3d& x : mesh.vertices) x = Eigen::Vector3d(x.x(), -x.z(), x.y());
}

}  // namespace upf
