// Scene checks of the liquids' viscosity parameters that no single range can state.
#pragma once

#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"

namespace upf {

// The liquids one solver moves share one viscous solve (solvers/fluid/implicit_viscosity.h), so
// they must agree on `implicit_viscosity`: a disagreement is a problem naming both materials.
void check_viscosity_keys(JsonInput& in, const SceneDescription& scene);

}  // namespace upf
