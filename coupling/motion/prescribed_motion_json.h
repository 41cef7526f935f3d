// The "motion" object of a kinematic body in a scene file (prescribed_motion.h). One of:
//
//   { "linear_velocity": [vx, vy, vz],      m/s, optional, default [0, 0, 0]
//     "angular_velocity": [wx, wy, wz] }    rad/s about the pivot, world axes, optional, default 0
//
//   { "keyframes": [                        at least one; times strictly increasing, >= 0
//       { "time": 0,                        s, required
//         "position": [0, 0, 0],            m, displacement, optional, default [0, 0, 0]
//         "rotation": { "axis": [0, 0, 1], "degrees": 0 } },   optional, default none
//       { "time": 1, "position": [0.2, 0, 0] } ],
//     "loop": 2.0 }                         s, optional: repeat with this period (>= last time)
//
// and, with either, "pivot": [x, y, z] (m, world): the point the body turns about. Keyed poses
// are displacements from where the scene placed the mesh: a key at [0, 0, 0] with no rotation
// means "where the scene put it". A rotation reads as a mesh's does (read_rotation()).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "coupling/motion/prescribed_motion.h"
#include "framework/scene/json_input.h"

namespace upf {

// Reads the motion object `node` at `path`; every problem goes to `input` under its JSON path
// (and the result is empty). Accepts the "pivot" key but leaves it to read_pivot().
std::optional<PrescribedMotion> read_prescribed_motion(const nlohmann::json& node,
                                                       const std::string& path, JsonInput& input);

// The motion object's "pivot", when given; nothing when absent (the caller picks its own, e.g.
// the mesh's centroid) or bad (reported to `input`).
std::optional<Eigen::Vector3d> read_pivot(const nlohmann::json& node, const std::string& path,
                                          JsonInput& input);

}  // namespace upf
