#include "coupling/mesh/mesh_validation.h"

#include "coupling/mesh/mesh_error.h"

namespace upf {

namespace {
// Below this fraction of the bounding box's squared diagonal, the total area is rounding noise.
constexpr double kRelativeAreaFloor = 1e-14;
}  // namespace

void require_usable_surface(const TriangleMesh& mesh, const std::string& where) {
  if (mesh.triangles.empty())
    throw mesh_error(mesh.source, where,
                     "contains no triangles (an empty mesh, or only points "
                     "and lines)");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      throw mesh_error(mesh.source, where,
                       "vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const std::uint32_t v : mesh.triangles[t])
      if (v >= mesh.vertices.size())
        throw mesh_error(mesh.source, where,
                         "triangle " + std::to_string(t) + " refers to vertex " +
                             std::to_string(v) + ", but there are only " +
                             std::to_string(mesh.vertices.size()));
  const double diagonal = bounding_box(mesh).diagonal().squaredNorm();
  if (!(surface_area(mesh) > kRelativeAreaFloor * diagonal))
    throw mesh_error(mesh.source, where,
                     "is degenerate: all " + std::to_string(mesh.triangles.size()) +
                         " triangles have zero area");
}

}  // namespace upf
