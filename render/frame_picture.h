// One picture of one frame: the particles as spheres (liquid, grains, and the walls, the near
// ones as glass), the bodies' meshes, and the overlays (title, time, colour bar).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/render_settings.h"
#include "render/run_frames.h"
#include "render/vtp_reader.h"

namespace upf::render {

// What a frame holds once read: the particles, the meshes of its other parts (bodies), and the
// liquid's surface meshes (frames/surface_NNNNN.vtp).
struct FrameData {
  double time = 0;
  PolyData particles;
  std::vector<PolyData> meshes;
  std::vector<PolyData> surfaces;
};

bool has_liquid_surface(const FrameData& frame);

// Reads a saved frame: its first part is the particles, and so is any other part that has a
// "type" point array and no triangles (the frozen particles, written once); files named
// surface_* are the liquid's surface; the others are bodies' meshes. Throws InputError naming a
// damaged file.
FrameData read_frame(const RunFrame& frame);

// The field values a picture colours by, mapped onto [low, high].
struct ColourScale {
  std::string field;
  double low = 0, high = 1;
};

struct PictureContext {
  RenderSettings settings;
  Camera camera;
  std::optional<ColourScale> scale;  // absent: colour by type or material
  double particle_spacing = 0.02;    // spheres are drawn with half of it as radius
  std::string title;                 // e.g. the scene's name
  int threads = 0;
};

// The values shown for `field` on particle `i` (speed: |velocity|); nullopt when the frame has
// no such field. Throws nothing.
std::optional<double> field_value(const PolyData& particles, const std::string& field,
                                  std::size_t i);
bool frame_has_field(const PolyData& particles, const std::string& field);

// The names a picture may be coloured by: type, material, speed, then the frame's fields.
std::vector<std::string> colour_choices(const PolyData& particles);

// `range`, or 0.5 either side of it when it is a single value (a field constant everywhere),
// so that colours stay defined.
std::array<double, 2> widened_if_flat(std::array<double, 2> range);

// The 1st and 99th percentiles of `field` over the moving (liquid and granular) particles;
// nullopt when none has a finite value.
std::optional<std::array<double, 2>> field_percentiles(const PolyData& particles,
                                                       const std::string& field);

// The field's name with its unit, for the fields every fluid solver writes ("pressure (Pa)");
// other fields by name alone.
std::string field_label(const std::string& field);

// A camera that shows every particle, with `up` as the picture's vertical (frame_box).
Camera camera_for_particles(const PolyData& particles, const Eigen::Vector3d& up, double aspect);

Image draw_frame(const FrameData& frame, const PictureContext& context);

}  // namespace upf::render
