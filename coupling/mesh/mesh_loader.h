// Loads a triangle mesh from a file with assimp (https://github.com/assimp/assimp): OBJ, STL
// (ASCII and binary), PLY, glTF 2.0 (.gltf, .glb) are tested; the other formats assimp reads
// work the same way. Polygons are triangulated; points and lines are dropped; every mesh of every
// node is placed with the node's transform and merged into one triangle soup; vertices at exactly
// the same position are joined (also across meshes), so a surface split into several meshes is
// still closed; triangles that join to fewer than three distinct vertices are dropped. Then the
// MeshTransform is applied (see mesh_transform.h). Coordinates are taken as the file stores them:
// no up-axis conversion.
#pragma once

#include <filesystem>
#include <string>

#include "coupling/mesh/mesh_transform.h"
#include "coupling/mesh/triangle_mesh.h"

namespace upf {

// Throws InputError at `where` (the JSON path that names the file, e.g. "/bodies/0/mesh"; empty:
// the file itself), its message naming the file, when: the file is missing, not a regular file
// or empty; its format is not supported; its header declares more vertices or faces than the
// file holds (PLY, OFF: declared_counts.h); assimp fails to read it (assimp's message is quoted);
// it has no triangles; a vertex is not finite; every triangle has zero area; the transform is
// invalid. Never aborts on a bad file.
TriangleMesh load_mesh(const std::filesystem::path& file, const MeshTransform& transform = {},
                       const std::string& where = {});

}  // namespace upf
