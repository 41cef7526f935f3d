// A mesh reference in a scene file, with its placement (the convention of mesh_transform.h):
//
//   { "file": "assets/meshes/l_block_mm.stl",      required; relative to the scene's folder
//     "units": "mm",                               optional, default "m"
//     "scale": 2  or  [1, 1, 2],                   optional, default 1; non-zero, negative mirrors
//     "rotation": { "axis": [0, 0, 1], "degrees": 90 },   optional, default none
//     "position": [0, 0.5, 0] }                    optional, default [0, 0, 0], metres
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "coupling/mesh/mesh_transform.h"
#include "framework/scene/json_input.h"

namespace upf {

struct MeshSource {
  std::filesystem::path file;
  MeshTransform transform;
};

// Reads the object at `path`; every problem goes to `input` (and the result is empty).
std::optional<MeshSource> read_mesh_source(const nlohmann::json& node, const std::string& path,
                                           const std::filesystem::path& base_directory,
                                           JsonInput& input);

// The optional "rotation": { "axis": [x, y, z], "degrees": d } of the object `node` at `path`
// (right-hand rule, any non-zero axis length); absent: the identity. Shared by everything that
// places or moves a mesh, so that a rotation reads the same everywhere. Problems go to `input`
// under path/rotation (and the result is empty).
std::optional<Eigen::Quaterniond> read_rotation(const nlohmann::json& node, const std::string& path,
                                                JsonInput& input);

}  // namespace upf
