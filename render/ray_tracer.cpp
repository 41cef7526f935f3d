#include "render/ray_tracer.h"

#include <embree3/rtcore.h>
#include <omp.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace upf::render {

namespace {

// Owners that release the Embree handles on every path out.
struct DeviceDeleter {
  void operator()(RTCDeviceTy* d) const { rtcReleaseDevice(d); }
};
struct SceneDeleter {
  void operator()(RTCSceneTy* s) const { rtcReleaseScene(s); }
};
using DevicePtr = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using ScenePtr = std::unique_ptr<RTCSceneTy, SceneDeleter>;

void add_spheres(RTCDevice device, RTCScene scene, const SphereSet& set) {
  if (set.centres.empty()) return;
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), set.centres.size()));
  for (std::size_t i = 0; i < set.centres.size(); ++i) {
    v[4 * i + 0] = set.centres[i].x();
    v[4 * i + 1] = set.centres[i].y();
    v[4 * i + 2] = set.centres[i].z();
    v[4 * i + 3] = set.radius;
  }
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(scene, g, 0);
  rtcReleaseGeometry(g);
}

void add_triangles(RTCDevice device, RTCScene scene, const TriangleSet& set) {
  if (set.triangles.empty()) return;
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), set.vertices.size()));
  std::memcpy(v, set.vertices.data(), set.vertices.size() * 3 * sizeof(float));
  auto* t = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), set.triangles.size()));
  std::memcpy(t, set.triangles.data(), set.triangles.size() * 3 * sizeof(std::uint32_t));
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(scene, g, 1);
  rtcReleaseGeometry(g);
}

RTCRayHit make_ray(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float tfar) {
  RTCRayHit rh{};
  rh.ray.org_x = o.x();
  rh.ray.org_y = o.y();
  rh.ray.org_z = o.z();
  rh.ray.dir_x = d.x();
  rh.ray.dir_y = d.y();
  rh.ray.dir_z = d.z();
  rh.ray.tnear = 0.f;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// Schlick's approximation of the Fresnel reflectance at an air-water interface (n = 1.33).
float schlick(float cos_incidence) {
  constexpr float r0 = 0.02f;  // ((1.33 - 1) / (1.33 + 1))^2
  const float m = 1.f - std::clamp(cos_incidence, 0.f, 1.f);
  return r0 + (1.f - r0) * m * m * m * m * m;
}

// Area-weighted vertex normals of a closed mesh, outward for counter-clockwise triangles.
std::vector<Eigen::Vector3f> vertex_normals(const TriangleSet& set) {
  std::vector<Eigen::Vector3f> n(set.vertices.size(), Eigen::Vector3f::Zero());
  for (const auto& t : set.triangles) {
    const Eigen::Vector3f face =
        (set.vertices[t[1]] - set.vertices[t[0]]).cross(set.vertices[t[2]] - set.vertices[t[0]]);
    for (const std::uint32_t v : t) n[v] += face;
  }
  for (auto& v : n) v = v.norm() > 0 ? v.normalized() : Eigen::Vector3f::UnitY();
  return n;
}

class Tracer {
 public:
  Tracer(const RenderScene& scene, const Camera& camera, const TraceSettings& settings)
      : scene_(scene), rays_(camera, settings.width, settings.height), settings_(settings) {
    // One build thread: the acceleration structure, and so every tie between equally near
    // hits, is the same on every run. Tracing itself runs on our OpenMP threads.
    device_.reset(rtcNewDevice("threads=1,set_affinity=0"));
    if (!device_)
      throw std::runtime_error("Embree could not start (error " +
                               std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    opaque_.reset(rtcNewScene(device_.get()));
    glass_.reset(rtcNewScene(device_.get()));
    water_.reset(rtcNewScene(device_.get()));
    add_spheres(device_.get(), opaque_.get(), scene.opaque);
    add_triangles(device_.get(), opaque_.get(), scene.meshes);
    add_spheres(device_.get(), glass_.get(), scene.glass);
    add_triangles(device_.get(), water_.get(), scene.water);
    rtcCommitScene(opaque_.get());
    rtcCommitScene(glass_.get());
    rtcCommitScene(water_.get());
    water_normals_ = vertex_normals(scene.water);
    if (rtcGetDeviceError(device_.get()) != RTC_ERROR_NONE)
      throw std::runtime_error("Embree could not build the scene (error " +
                               std::to_string(int(rtcGetDeviceError(device_.get()))) + ")");
    // Key light from above, a little from the camera's left and from behind it.
    light_ = (1.0f * rays_.up() - 0.45f * rays_.right() - 0.35f * rays_.forward()).normalized();
  }

  Colour pixel(int x, int y) const {
    const int n = settings_.samples_per_axis;
    Colour sum = Colour::Zero();
    for (int sy = 0; sy < n; ++sy)
      for (int sx = 0; sx < n; ++sx)
        sum += sample(double(x) + (sx + 0.5) / n, double(y) + (sy + 0.5) / n);
    return sum / float(n * n);
  }

 private:
  Colour background(const Eigen::Vector3f& direction) const {
    // A soft sky: lighter towards the top of the picture.
    const float s = 0.5f * (1.f + direction.dot(rays_.up()));
    return (1 - s) * Colour(0.74f, 0.77f, 0.81f) + s * Colour(0.95f, 0.96f, 0.98f);
  }

  // What a ray from `origin` along `direction` sees: opaque things, the sky, and water, whose
  // surface splits the ray into a reflected and a refracted one (up to kWaterDepth surfaces).
  // `inside`: the ray runs through water, which absorbs along it. Sets `first_hit` to the
  // distance of the first thing hit (infinity for the sky).
  Colour trace(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction, bool inside,
               int depth, RTCIntersectContext& context, float& first_hit) const {
    RTCRayHit rh = make_ray(origin, direction, std::numeric_limits<float>::infinity());
    rtcIntersect1(opaque_.get(), &context, &rh);
    const float opaque_t = rh.ray.tfar;
    const bool opaque_hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    RTCRayHit wh = make_ray(origin, direction, opaque_hit ? opaque_t : rh.ray.tfar);
    if (!scene_.water.triangles.empty()) rtcIntersect1(water_.get(), &context, &wh);
    const bool water_hit = wh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    first_hit = water_hit ? wh.ray.tfar : opaque_t;

    Colour c;
    if (water_hit && depth < kWaterDepth) {
      c = water_surface(origin, direction, wh, depth, context);
    } else if (opaque_hit) {
      Eigen::Vector3f n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
      n.normalize();
      if (n.dot(direction) > 0) n = -n;  // triangles are lit from whichever side we see
      const Colour base = rh.hit.geomID == 0 ? scene_.opaque.colours[rh.hit.primID]
                                             : scene_.meshes.colours[rh.hit.primID];
      const Eigen::Vector3f p = origin + opaque_t * direction;
      c = shade(base, p + 0.05f * scene_.opaque.radius * n, n, direction, context);
    } else {
      c = background(direction);
    }
    if (inside && std::isfinite(first_hit)) {
      // Beer-Lambert along the path inside, with the light scattered in tending to the deep
      // colour: red goes first, so depth turns the water blue.
      const Eigen::Array3f kept =
          (-scene_.water_absorption * (first_hit / scene_.water_scale)).exp();
      c = (kept * c.array() + (1.f - kept) * scene_.water_deep.array()).matrix();
    }
    return c;
  }

  // A ray meets the water's surface: Fresnel-weighted reflection and refraction.
  Colour water_surface(const Eigen::Vector3f& origin, const Eigen::Vector3f& d, const RTCRayHit& wh,
                       int depth, RTCIntersectContext& context) const {
    const auto& t = scene_.water.triangles[wh.hit.primID];
    const float u = wh.hit.u, v = wh.hit.v;
    Eigen::Vector3f n =
        ((1 - u - v) * water_normals_[t[0]] + u * water_normals_[t[1]] + v * water_normals_[t[2]])
            .normalized();
    const Eigen::Vector3f p = origin + wh.ray.tfar * d;
    // Entering or leaving: by the side of the (outward) surface the ray comes from.
    const bool entering = n.dot(d) < 0;
    if (!entering) n = -n;  // n now faces the ray
    const float cos_i = -n.dot(d);
    const float eta = entering ? 1.f / 1.33f : 1.33f;
    const float k = 1.f - eta * eta * (1.f - cos_i * cos_i);
    const float offset = 1e-4f * scene_.water_scale;
    const Eigen::Vector3f reflected = (d + 2.f * cos_i * n).normalized();
    const float fresnel = k < 0 ? 1.f : schlick(entering ? cos_i : std::sqrt(k));
    float ignored = 0;
    Colour reflection;
    if (entering) {
      // Outside, the reflection is of the sky, with the key light's glint.
      const float glint = std::pow(std::max(0.f, reflected.dot(light_)), 400.f);
      reflection = background(reflected) + Colour::Constant(3.f * glint);
    } else {
      reflection = trace(p + offset * n, reflected, true, depth + 1, context, ignored);
    }
    if (k < 0) return reflection;  // total internal reflection
    const Eigen::Vector3f refracted = (eta * d + (eta * cos_i - std::sqrt(k)) * n).normalized();
    const Colour transmission =
        trace(p - offset * n, refracted, entering, depth + 1, context, ignored);
    return fresnel * reflection + (1.f - fresnel) * transmission;
  }

  Colour sample(double x, double y) const {
    const Ray ray = rays_.through(x, y);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    float hit_t = 0;
    Colour c = trace(ray.origin, ray.direction, false, 0, context, hit_t);
    if (!scene_.glass.centres.empty()) {
      RTCRay through = make_ray(ray.origin, ray.direction, hit_t).ray;
      rtcOccluded1(glass_.get(), &context, &through);
      if (through.tfar < 0)  // a glass sphere lies in front: tint what is behind
        c = (1 - scene_.glass_opacity) * c + scene_.glass_opacity * scene_.glass_tint;
    }
    return c;
  }

  Colour shade(const Colour& base, const Eigen::Vector3f& p, const Eigen::Vector3f& n,
               const Eigen::Vector3f& view, RTCIntersectContext& context) const {
    float light = std::max(0.f, n.dot(light_));
    if (light > 0) {
      RTCRay shadow = make_ray(p, light_, std::numeric_limits<float>::infinity()).ray;
      rtcOccluded1(opaque_.get(), &context, &shadow);
      if (shadow.tfar < 0) light *= 0.25f;
    }
    const float headlight = std::max(0.f, -n.dot(view));
    const Eigen::Vector3f half = (light_ - view).normalized();
    const float specular = light > 0.3f ? std::pow(std::max(0.f, n.dot(half)), 48.f) : 0.f;
    return (0.22f + 0.58f * light + 0.25f * headlight) * base + Colour::Constant(0.25f * specular);
  }

  const RenderScene& scene_;
  CameraRays rays_;
  TraceSettings settings_;
  DevicePtr device_;
  ScenePtr opaque_, glass_, water_;
  std::vector<Eigen::Vector3f> water_normals_;
  Eigen::Vector3f light_;
  // Water surfaces one ray passes on its way: in and out of a splash, and a reflection inside.
  static constexpr int kWaterDepth = 6;
};

}  // namespace

Image ray_trace(const RenderScene& scene, const Camera& camera, const TraceSettings& settings) {
  if (settings.width < 1 || settings.height < 1 || settings.samples_per_axis < 1)
    throw std::invalid_argument("ray_trace: the image size and samples must be positive");
  const Tracer tracer(scene, camera, settings);
  Image image(settings.width, settings.height);
  const int threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) image.at(x, y) = tracer.pixel(x, y);
  return image;
}

}  // namespace upf::render
