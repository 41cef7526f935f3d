// The rigid material kind: boundary particles sampled on a closed mesh that move with a Bullet
// rigid body (coupling/bodies). No particle solver moves them.
#pragma once

#include "framework/materials/material.h"

namespace upf {

MaterialKind rigid_material_kind();

// Contact parameters shared by rigid and frozen materials (Bullet's restitution and friction).
std::vector<ParamSpec> contact_params();

}  // namespace upf
