#include "render/frame_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "render/ray_tracer.h"

namespace upf::render {

namespace {

ParticleType type_of(const PolyData& p, std::size_t i) {
  const VtpArray* type = p.point_array("type");
  const double t = type ? type->values[i] : 0;
  return t >= 0 && t < kParticleTypeCount ? ParticleType(int(t)) : ParticleType::Liquid;
}

// Frozen particles within a few spacings of a face of the walls' bounding box, on the side the
// camera looks from: the tank's near walls. Drawn as glass so they do not hide the inside.
class NearWalls {
 public:
  NearWalls(const PolyData& p, const Eigen::Vector3f& eye, float thickness) : eye_(eye) {
    lo_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
    hi_ = -lo_;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      if (type_of(p, i) != ParticleType::Frozen) continue;
      lo_ = lo_.cwiseMin(p.points[i]);
      hi_ = hi_.cwiseMax(p.points[i]);
    }
    thickness_ = thickness;
  }
  bool contains(const Eigen::Vector3f& x) const {
    for (int a = 0; a < 3; ++a) {
      if (eye_[a] < lo_[a] && x[a] < lo_[a] + thickness_) return true;
      if (eye_[a] > hi_[a] && x[a] > hi_[a] - thickness_) return true;
    }
    return false;
  }

 private:
  Eigen::Vector3f eye_, lo_, hi_;
  float thickness_ = 0;
};

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

void draw_colour_bar(Image& image, const ColourScale& scale, int font) {
  const int bar_w = std::max(8, image.width() / 60);
  const int bar_h = image.height() / 2;
  const int x0 = image.width() - bar_w - 12 * font - Image::text_width("-0.000e+00", font);
  const int y0 = (image.height() - bar_h) / 2;
  const Colour ink(0.1f, 0.1f, 0.12f);
  image.fill_rect(x0 - 1, y0 - 1, x0 + bar_w + 1, y0 + bar_h + 1, ink);
  for (int y = 0; y < bar_h; ++y)
    image.fill_rect(x0, y0 + y, x0 + bar_w, y0 + y + 1, viridis(1.0 - (y + 0.5) / bar_h));
  for (int k = 0; k <= 4; ++k) {
    const double s = k / 4.0;
    const int y = y0 + int(std::lround((1 - s) * (bar_h - 1)));
    image.fill_rect(x0 + bar_w, y, x0 + bar_w + 3 * font, y + std::max(1, font / 2), ink);
    image.draw_text(x0 + bar_w + 4 * font, y - Image::text_height(font) / 2,
                    format_number(scale.low + s * (scale.high - scale.low)), ink, font);
  }
  const std::string label = field_label(scale.field);
  image.draw_text(std::min(x0 - Image::text_width(label, font) / 2 + bar_w / 2,
                           image.width() - Image::text_width(label, font) - 2 * font),
                  y0 - 4 * font - Image::text_height(font), label, ink, font);
}

}  // namespace

std::string field_label(const std::string& field) {
  if (field == "speed" || field == "velocity") return field + " (m/s)";
  if (field == "density") return "density (kg/m3)";
  if (field == "pressure") return "pressure (Pa)";
  return field;
}

bool frame_has_field(const PolyData& particles, const std::string& field) {
  if (field == "speed") return particles.point_array("velocity") != nullptr;
  return particles.point_array(field) != nullptr;
}

std::optional<double> field_value(const PolyData& particles, const std::string& field,
                                  std::size_t i) {
  const VtpArray* a = particles.point_array(field == "speed" ? "velocity" : field);
  if (!a || i >= a->tuples()) return std::nullopt;
  return a->magnitude(i);
}

std::vector<std::string> colour_choices(const PolyData& particles) {
  std::vector<std::string> names{"type", "material", "speed"};
  for (const auto& a : particles.point_data)
    if (a.name != "type" && a.name != "material" && a.name != "id" && a.name != "velocity")
      names.push_back(a.name);
  return names;
}

std::optional<std::array<double, 2>> field_percentiles(const PolyData& p,
                                                       const std::string& field) {
  std::vector<double> v;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const ParticleType t = type_of(p, i);
    if (t == ParticleType::Frozen || t == ParticleType::Rigid) continue;
    if (auto x = field_value(p, field, i); x && std::isfinite(*x)) v.push_back(*x);
  }
  if (v.empty()) return std::nullopt;
  std::sort(v.begin(), v.end());
  return std::array<double, 2>{v[std::size_t(0.01 * double(v.size() - 1))],
                               v[std::size_t(0.99 * double(v.size() - 1))]};
}

std::array<double, 2> widened_if_flat(std::array<double, 2> range) {
  const auto [low, high] = range;
  if (high - low < 1e-12 * std::max(1.0, std::abs(high))) return {low - 0.5, high + 0.5};
  return range;
}

namespace {
// Appends the points of `more` to `into`, keeping the point arrays both have (a frozen piece
// written once holds the same arrays as the frames).
void append_points(PolyData& into, const PolyData& more) {
  std::vector<VtpArray> kept;
  for (VtpArray& a : into.point_data) {
    const VtpArray* b = more.point_array(a.name);
    if (!b || b->components != a.components) continue;
    a.values.insert(a.values.end(), b->values.begin(), b->values.end());
    kept.push_back(std::move(a));
  }
  into.point_data = std::move(kept);
  into.points.insert(into.points.end(), more.points.begin(), more.points.end());
}
}  // namespace

bool has_liquid_surface(const FrameData& frame) {
  return !frame.surfaces.empty();
}

FrameData read_frame(const RunFrame& f) {
  FrameData data;
  data.time = f.time;
  data.particles = read_vtp(f.parts.front());
  for (std::size_t k = 1; k < f.parts.size(); ++k) {
    PolyData part = read_vtp(f.parts[k]);
    if (part.triangles.empty() && part.point_array("type"))
      append_points(data.particles, part);  // particles of their own file (frames/frozen.vtp)
    else if (f.parts[k].filename().string().rfind("surface_", 0) == 0)
      data.surfaces.push_back(std::move(part));  // FrameWriter's liquid surface
    else
      data.meshes.push_back(std::move(part));
  }
  return data;
}

Camera camera_for_particles(const PolyData& particles, const Eigen::Vector3d& up, double aspect) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& x : particles.points) {
    lo = lo.cwiseMin(x.cast<double>());
    hi = hi.cwiseMax(x.cast<double>());
  }
  if (particles.points.empty()) lo = hi = Eigen::Vector3d::Zero();
  return frame_box(lo, hi, up, aspect);
}

namespace {
// The water's absorption is set per length of its bounding box's diagonal, so a 10 cm tank and
// a 10 m pool both look like deep water rather than clear film or ink.
float water_depth_scale(const TriangleSet& water) {
  if (water.vertices.empty()) return 1.f;
  Eigen::Vector3f lo = water.vertices.front(), hi = lo;
  for (const auto& v : water.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return std::max(1e-6f, (hi - lo).norm());
}
}  // namespace

Image draw_frame(const FrameData& frame, const PictureContext& context) {
  const RenderSettings& settings = context.settings;
  const PolyData& p = frame.particles;
  RenderScene scene;
  const float radius = float(0.5 * context.particle_spacing);
  scene.opaque.radius = scene.glass.radius = radius;
  const NearWalls near_walls(p, context.camera.position.cast<float>(),
                             float(3.0 * context.particle_spacing));
  bool have_body_meshes = false;
  for (const PolyData& m : frame.meshes) have_body_meshes |= m.cell_array("body") != nullptr;
  const VtpArray* material = p.point_array("material");
  bool coloured_by_field = false;  // a particle drawn takes its colour from the scale

  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const ParticleType type = type_of(p, i);
    Colour c = type_colour(type);
    if (type == ParticleType::Frozen) {
      if (settings.walls == WallStyle::Hidden) continue;
      if (settings.walls == WallStyle::Glass && near_walls.contains(p.points[i])) {
        scene.glass.centres.push_back(p.points[i]);
        scene.glass.colours.push_back(c);
        continue;
      }
    } else if (type == ParticleType::Rigid && have_body_meshes) {
      continue;  // the body's mesh stands for its boundary particles
    } else if (type == ParticleType::Liquid && settings.surface) {
      continue;  // the water surface stands for the liquid
    } else if (context.scale) {
      coloured_by_field = true;
      const double v = field_value(p, context.scale->field, i).value_or(std::nan(""));
      const double span = context.scale->high - context.scale->low;
      c = viridis(span > 0 ? (v - context.scale->low) / span : 0.5);
    } else if (settings.color_by == "material" && material) {
      c = material_colour(std::uint32_t(material->values[i]));
    }
    scene.opaque.centres.push_back(p.points[i]);
    scene.opaque.colours.push_back(c);
  }
  // Bodies as meshes; the liquid's surface as water in surface mode (otherwise the particles
  // show the liquid, and the surface is not drawn).
  auto add_meshes = [](const std::vector<PolyData>& meshes, TriangleSet& set, Colour colour) {
    for (const PolyData& m : meshes) {
      const std::uint32_t base = std::uint32_t(set.vertices.size());
      set.vertices.insert(set.vertices.end(), m.points.begin(), m.points.end());
      for (const auto& t : m.triangles) {
        set.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
        set.colours.push_back(colour);
      }
    }
  };
  add_meshes(frame.meshes, scene.meshes, type_colour(ParticleType::Rigid));
  if (settings.surface) add_meshes(frame.surfaces, scene.water, type_colour(ParticleType::Liquid));
  scene.water_scale = water_depth_scale(scene.water);

  TraceSettings trace;
  trace.width = settings.width;
  trace.height = settings.height;
  trace.samples_per_axis = settings.samples_per_axis;
  trace.threads = context.threads;
  Image image = ray_trace(scene, context.camera, trace);

  const int font = std::max(1, int(std::lround(settings.height / 300.0)));
  const Colour ink(0.1f, 0.1f, 0.12f);
  char time_text[64];
  std::snprintf(time_text, sizeof time_text, "t = %.3f s", frame.time);
  image.draw_text(4 * font, 4 * font, context.title, ink, font);
  image.draw_text(4 * font, 6 * font + Image::text_height(font), time_text, ink, font);
  // With the liquid drawn as water, the bar stays only for what it colours (grains, say).
  if (context.scale && coloured_by_field) draw_colour_bar(image, *context.scale, font);
  return image;
}

}  // namespace upf::render
