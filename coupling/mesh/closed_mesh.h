// Is the surface closed, so that it bounds a volume? A dynamic body needs that: its mass and
// inertia are integrals over the enclosed volume, and fluid must not leak into it.
//
// Closed here means: every edge is shared by exactly two triangles that run it in opposite
// directions (an oriented 2-manifold without boundary, edge-wise; two closed surfaces touching
// at one vertex still pass).
#pragma once

#include <cstddef>
#include <string>

#include "coupling/mesh/triangle_mesh.h"

namespace upf {

struct ClosedMeshReport {
  std::size_t boundary_edges = 0;      // used by one triangle: the rim of a hole
  std::size_t non_manifold_edges = 0;  // used by three or more triangles
  std::size_t misoriented_edges = 0;   // two triangles run it the same way: windings disagree
  bool closed() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && misoriented_edges == 0;
  }
};

ClosedMeshReport check_closed(const TriangleMesh& mesh);
inline bool is_closed(const TriangleMesh& mesh) {
  return check_closed(mesh).closed();
}

// Throws InputError at `where` (a JSON path; empty: the file), naming mesh.source and counting
// each kind of bad edge, unless the mesh is closed and consistently oriented.
void require_closed(const TriangleMesh& mesh, const std::string& where);

}  // namespace upf
