// One closed triangle mesh in world coordinates: a body's surface in its current pose, or the
// liquid's surface. Plain data shared by the bodies (core) and the writers and renderers around it.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace upf {

struct MeshPiece {
  std::string name;  // e.g. the body's name; used in error messages, not written to files
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into `vertices`
};

}  // namespace upf
