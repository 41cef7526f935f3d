// The "bodies" section of scene files: rigid bodies and mesh obstacles.
//
//   "bodies": [
//     { "name": "crate",                           optional; default "body<index>"
//       "material": "wood",                        a rigid material: Bullet moves it;
//                                                  a frozen one: a static or kinematic obstacle
//       "mesh": { "file": ..., "scale": ..., "rotation": ..., "position": ..., "units": ... },
//       "velocity": [0, 0, 0],                     rigid only, m/s, initial
//       "angular_velocity": [0, 0, 0],             rigid only, rad/s, initial, world axes
//       "motion": { ... } }                        frozen only: prescribed_motion_json.h
//   ]
//
// Reading loads each mesh (mesh_loader.h), checks that a rigid body's mesh is closed, computes
// its mass properties and samples every surface at the particle spacing, so that `upf validate`
// finds every broken mesh before anything runs.
#pragma once

#include "framework/scene/scene_section.h"
#include "framework/solver/registry.h"

namespace upf {

SceneSection bodies_scene_section();

// Registers what coupling/ adds to scene files.
void register_coupling(Registry& registry);

}  // namespace upf
