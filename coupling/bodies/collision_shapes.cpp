#include "coupling/bodies/collision_shapes.h"

#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <LinearMath/btConvexHullComputer.h>

#include <cmath>

namespace upf {

double convex_hull_volume(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  btConvexHullComputer hull;
  hull.compute(coords.data(), int(3 * sizeof(double)), int(points.size()), 0, 0);
  // Fan-triangulate each face about its first vertex; the sum of signed tetrahedra to the
  // origin is the volume.
  double volume = 0;
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const btVector3& a = hull.vertices[first->getSourceVertex()];
    const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace();
    while (e->getTargetVertex() != first->getSourceVertex()) {
      const btVector3& b = hull.vertices[e->getSourceVertex()];
      const btVector3& c = hull.vertices[e->getTargetVertex()];
      volume += double(a.dot(b.cross(c))) / 6.0;
      e = e->getNextEdgeOfFace();
    }
  }
  return std::abs(volume);
}

OwnedShape make_body_shape(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& local,
                           BodyKind kind, double volume, double margin) {
  OwnedShape out;
  if (kind == BodyKind::Dynamic) {
    const double hull = convex_hull_volume(local);
    if (std::abs(hull - volume) <= 0.005 * volume) {
      auto shape = std::make_unique<btConvexHullShape>();
      for (const auto& v : local) shape->addPoint(btVector3(v.x(), v.y(), v.z()), false);
      shape->recalcLocalAabb();
      shape->optimizeConvexHull();
      shape->setMargin(btScalar(margin));
      out.shape = std::move(shape);
      out.convex = true;
      return out;
    }
  }
  for (const auto& v : local) out.vertex_data.insert(out.vertex_data.end(), {v.x(), v.y(), v.z()});
  for (const auto& t : mesh.triangles)
    out.index_data.insert(out.index_data.end(), {int(t[0]), int(t[1]), int(t[2])});
  out.triangles = std::make_unique<btTriangleIndexVertexArray>(
      int(mesh.triangles.size()), out.index_data.data(), int(3 * sizeof(int)), int(local.size()),
      out.vertex_data.data(), int(3 * sizeof(btScalar)));
  if (kind == BodyKind::Dynamic) {
    auto shape = std::make_unique<btGImpactMeshShape>(out.triangles.get());
    shape->setMargin(btScalar(margin));
    shape->updateBound();
    out.shape = std::move(shape);
  } else {
    auto shape = std::make_unique<btBvhTriangleMeshShape>(out.triangles.get(), true);
    shape->setMargin(btScalar(margin));
    out.shape = std::move(shape);
  }
  return out;
}

}  // namespace upf
