// Colours for pictures: a fixed colour per particle type, a categorical palette for materials,
// and the viridis map for fields (van der Walt & Smith 2015, matplotlib's default: perceptually
// uniform, readable in grey and by colour-blind viewers).
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "framework/core/particle_type.h"

namespace upf::render {

using Colour = Eigen::Vector3f;  // linear RGB in [0, 1]

Colour type_colour(ParticleType type);
Colour material_colour(std::uint32_t material);
// viridis(s) for s in [0, 1]; s outside is clamped, NaN gives magenta so it stands out.
Colour viridis(double s);

}  // namespace upf::render
