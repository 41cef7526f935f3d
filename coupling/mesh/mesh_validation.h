// The checks every loaded mesh passes before anything samples or weighs it.
#pragma once

#include <string>

#include "coupling/mesh/triangle_mesh.h"

namespace upf {

// Throws an InputError naming mesh.source (at `where`, a JSON path; empty: the file) when the
// mesh has no triangles, a non-finite vertex, a triangle index out of range, or no area at all
// (every triangle degenerate: all vertices on one point or one line).
void require_usable_surface(const TriangleMesh& mesh, const std::string& where);

}  // namespace upf
