// The colour range the viewer uses for a field when the scene sets none: the shown frame's own.
#pragma once

#include <optional>
#include <string>

#include "render/frame_picture.h"

namespace upf::viewer {

// The colour scale for `field` over the moving particles of this frame (1st to 99th
// percentile); nullopt for "type" and "material" or a field the frame lacks.
std::optional<render::ColourScale> frame_scale(const render::PolyData& particles,
                                               const std::string& field);

}  // namespace upf::viewer
