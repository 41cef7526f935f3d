#include "coupling/mesh/triangle_mesh.h"

#include <utility>

namespace upf {

Eigen::Vector3d triangle_area_vector(const TriangleMesh& mesh, std::size_t triangle) {
  const auto& t = mesh.triangles[triangle];
  const Eigen::Vector3d& a = mesh.vertices[t[0]];
  return (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
}

double triangle_area(const TriangleMesh& mesh, std::size_t triangle) {
  return 0.5 * triangle_area_vector(mesh, triangle).norm();
}

double surface_area(const TriangleMesh& mesh) {
  double area = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) area += triangle_area(mesh, t);
  return area;
}

Eigen::AlignedBox3d bounding_box(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;  // empty until extended
  for (const auto& v : mesh.vertices) box.extend(v);
  return box;
}

void flip_winding(TriangleMesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace upf
