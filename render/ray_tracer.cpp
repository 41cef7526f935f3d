#include "render/ray_tracer.h"

#include <embree3/rtcore.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

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
    add_spheres(device_.get(), opaque_.get(), scene.opaque);
    add_triangles(device_.get(), opaque_.get(), scene.meshes);
    add_spheres(device_.get(), glass_.get(), scene.glass);
    rtcCommitScene(opaque_.get());
    rtcCommitScene(glass_.get());
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
  Colour background(const Ray& ray) const {
    // A soft sky: lighter towards the top of the picture.
    const float s = 0.5f * (1.f + ray.direction.dot(rays_.up()));
    return (1 - s) * Colour(0.74f, 0.77f, 0.81f) + s * Colour(0.95f, 0.96f, 0.98f);
  }

  Colour sample(double x, double y) const {
    const Ray ray = rays_.through(x, y);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = make_ray(ray.origin, ray.direction, std::numeric_limits<float>::infinity());
    rtcIntersect1(opaque_.get(), &context, &rh);
    Colour c;
    const float hit_t = rh.ray.tfar;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
      c = background(ray);
    } else {
      Eigen::Vector3f n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
      n.normalize();
      if (n.dot(ray.direction) > 0) n = -n;  // triangles are lit from whichever side we see
      const Colour base = rh.hit.geomID == 0 ? scene_.opaque.colours[rh.hit.primID]
                                             : scene_.meshes.colours[rh.hit.primID];
      const Eigen::Vector3f p = ray.origin + hit_t * ray.direction;
      c = shade(base, p + 0.05f * scene_.opaque.radius * n, n, ray.direction, context);
    }
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
  ScenePtr opaque_, glass_;
  Eigen::Vector3f light_;
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
