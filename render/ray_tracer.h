// Draws spheres and triangle meshes with Embree (Wald et al. 2014, "Embree: a kernel framework
// for efficient CPU ray tracing"; Debian's libembree 3): one primary ray per sample, Lambert
// shading with a soft headlight, shadows from one directional key light, "glass" spheres that
// only tint what lies behind them (the near walls of a tank, so the liquid stays visible), and
// water: a closed surface mesh, smooth-shaded, that reflects the sky by Schlick's Fresnel
// approximation (Schlick 1994) and refracts by Snell's law with n = 1.33, absorbing along the
// path inside by Beer-Lambert, red first, so depth turns it blue.
//
// Why a ray tracer rather than OpenGL: it needs no display, no GPU and no GL context (EGL or
// OSMesa set-up differs per machine), renders a particle as an exact sphere, and gives shadows,
// which show depth in a still picture, for free. Each pixel is independent, so the picture is the
// same for any thread count.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "render/camera.h"
#include "render/image.h"

namespace upf::render {

struct SphereSet {
  std::vector<Eigen::Vector3f> centres;
  std::vector<Colour> colours;
  float radius = 0.01f;
};

struct TriangleSet {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Colour> colours;  // one per triangle
};

struct RenderScene {
  SphereSet opaque;  // liquid, grains, bodies' particles, walls seen from inside
  SphereSet glass;   // near walls: tint only, cast no shadow
  TriangleSet meshes;
  // The liquid's surface, a closed mesh with outward (counter-clockwise) triangles; it casts no
  // shadow. Absorption is per water_scale metres (the water's extent), so any size looks alike.
  TriangleSet water;
  float water_scale = 1.f;
  Eigen::Array3f water_absorption{9.0f, 3.2f, 1.6f};  // per water_scale, red, green, blue
  Colour water_deep{0.02f, 0.16f, 0.30f};  // what light scattered inside the water tends to
  Colour glass_tint{0.82f, 0.86f, 0.92f};
  float glass_opacity = 0.18f;
};

struct TraceSettings {
  int width = 1280, height = 720;
  int samples_per_axis = 2;  // 2: 4 rays per pixel (anti-aliasing)
  int threads = 0;           // 0: OpenMP's default
};

// Throws std::runtime_error when Embree cannot start (the message says why).
Image ray_trace(const RenderScene& scene, const Camera& camera, const TraceSettings& settings);

}  // namespace upf::render
