// Bullet collision shapes that fit a triangle mesh (Bullet 3 user manual, "Collision Shapes";
// https://github.com/bulletphysics/bullet3/blob/master/docs/Bullet_User_Manual.pdf):
//   dynamic, convex mesh       btConvexHullShape over the vertices (fast, exact for a convex mesh);
//   dynamic, non-convex mesh   btGImpactMeshShape (concave moving triangle mesh);
//   static or kinematic mesh   btBvhTriangleMeshShape (concave, does not deform);
//   container walls            one btBoxShape per wall slab.
// A mesh counts as convex when its hull's volume is within 0.5 % of its own.
#pragma once

#include <btBulletCollisionCommon.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "coupling/bodies/body_source.h"
#include "coupling/mesh/triangle_mesh.h"

namespace upf {

// A shape and the arrays it points into (Bullet's triangle meshes do not copy them).
struct OwnedShape {
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btTriangleIndexVertexArray> triangles;
  std::vector<btScalar> vertex_data;
  std::vector<int> index_data;
  bool convex = false;
};

// `local_vertices` are the mesh's vertices in the body frame. `margin` is Bullet's collision
// margin in metres: small against the particle spacing, so contacts happen where the surface is.
OwnedShape make_body_shape(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& local,
                           BodyKind kind, double volume, double margin);

// Volume of the convex hull of `points` (Bullet's hull computer).
double convex_hull_volume(const std::vector<Eigen::Vector3d>& points);

}  // namespace upf
