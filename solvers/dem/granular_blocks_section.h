// The scene key "granular_blocks": boxes filled with grains on a cubic lattice of pitch one grain
// diameter (touching grains), like fluid blocks for liquids. Each block names a granular material
// and must lie inside a container.
#pragma once

#include "framework/scene/scene_section.h"

namespace upf {

SceneSection granular_blocks_scene_section();

}  // namespace upf
