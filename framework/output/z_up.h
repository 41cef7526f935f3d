// upf scenes are Y-up (gravity along -y by default); Blender is Z-up and its PLY importer has no
// axis option. "ply_up": "z" writes the PLY files turned by +90 degrees about x, which takes +y
// to +z: (x, y, z) -> (x, -z, y). A proper rotation, so triangles keep their winding.
#pragma once

#include "framework/core/mesh_piece.h"
#include "framework/particles/particles.h"

namespace upf {

inline Vec3 to_z_up(const Vec3& v) {
  return {v.x, -v.z, v.y};
}

// Positions, velocities and every vector field of `p` turned Z-up.
void turn_to_z_up(Particles& p);
// The vertices of `mesh` turned Z-up.
void turn_to_z_up(MeshPiece& mesh);

}  // namespace upf
