#include "render/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace upf::render {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Any unit vector not parallel to `v`.
Eigen::Vector3d other_than(const Eigen::Vector3d& v) {
  return std::abs(v.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
}
}  // namespace

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : origin_(camera.position), width_(width), height_(height) {
  forward_ = (camera.target - camera.position).normalized();
  Eigen::Vector3d up = camera.up.normalized();
  if (std::abs(forward_.dot(up)) > 0.999) up = other_than(forward_);
  right_ = forward_.cross(up).normalized();
  up_ = right_.cross(forward_);
  half_height_ = std::tan(camera.fov_degrees * kPi / 360.0);
  half_width_ = half_height_ * double(width) / double(height);
}

Ray CameraRays::through(double x, double y) const {
  const double u = (2.0 * x / width_ - 1.0) * half_width_;
  const double v = (1.0 - 2.0 * y / height_) * half_height_;
  const Eigen::Vector3d d = (forward_ + u * right_ + v * up_).normalized();
  return {origin_.cast<float>(), d.cast<float>()};
}

Camera frame_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector3d& up,
                 double aspect) {
  Camera c;
  c.up = up.norm() > 0 ? up.normalized() : Eigen::Vector3d::UnitY();
  c.target = 0.5 * (lo + hi);
  // Front-right and above: between two horizontal axes, raised by about 25 degrees.
  const Eigen::Vector3d side = other_than(c.up).cross(c.up).normalized();
  const Eigen::Vector3d front = c.up.cross(side).normalized();
  const Eigen::Vector3d back = (0.45 * side + 1.0 * front + 0.5 * c.up).normalized();
  const Eigen::Vector3d forward = -back;
  const Eigen::Vector3d right = forward.cross(c.up).normalized();
  const Eigen::Vector3d view_up = right.cross(forward);
  // The nearest distance at which every corner of the box lies inside 90 % of the picture: a
  // corner q (from the target) at distance d sits at depth d + q.forward, and must satisfy
  // |q.right| <= m tan(half width) depth and |q.up| <= m tan(half height) depth.
  const double margin = 0.9;
  const double tan_h = std::tan(c.fov_degrees * kPi / 360.0) * margin;
  const double tan_w = tan_h * aspect;
  double distance = 1e-3;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                 (k & 4) ? hi.z() : lo.z());
    const Eigen::Vector3d q = corner - c.target;
    distance = std::max(distance, std::abs(q.dot(right)) / tan_w - q.dot(forward));
    distance = std::max(distance, std::abs(q.dot(view_up)) / tan_h - q.dot(forward));
  }
  c.position = c.target + back * distance;
  return c;
}

}  // namespace upf::render
