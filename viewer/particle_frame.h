// What the viewer hands the ray tracer for a scene stepped live: the world's particles in the
// form read_vtp gives for a saved frame, so one renderer (render/frame_picture.h) draws both.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "framework/particles/particles.h"
#include "render/camera.h"
#include "render/frame_picture.h"

namespace upf::viewer {

// Points, "type", "material", "velocity" (3 components) and every exported field (a vector
// field with 3 components), as write_vtp would write them.
render::PolyData to_poly_data(const Particles& particles);

// The colour scale for `field` over the moving particles of this frame (1st to 99th
// percentile); nullopt for "type" and "material" or a field the frame lacks.
std::optional<render::ColourScale> frame_scale(const render::PolyData& particles,
                                               const std::string& field);

}  // namespace upf::viewer
