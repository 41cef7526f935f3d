#include "viewer/orbit_camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace upf::viewer {

namespace {
constexpr double kMaxPitch = 1.55;  // just short of straight up or down (radians)
}

OrbitCamera::OrbitCamera(const render::Camera& start)
    : target_(start.target),
      up_(start.up.norm() > 0 ? start.up.normalized() : Eigen::Vector3d::UnitY()),
      fov_(start.fov_degrees) {
  const Eigen::Vector3d other =
      std::abs(up_.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  e1_ = (other - other.dot(up_) * up_).normalized();
  e2_ = up_.cross(e1_);
  const Eigen::Vector3d offset = start.position - start.target;
  distance_ = std::max(offset.norm(), 1e-6);
  yaw_ = std::atan2(offset.dot(e2_), offset.dot(e1_));
  pitch_ = std::asin(std::clamp(offset.dot(up_) / distance_, -1.0, 1.0));
}

void OrbitCamera::rotate(double dx, double dy) {
  yaw_ -= 0.01 * dx;
  pitch_ = std::clamp(pitch_ + 0.01 * dy, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dx, double dy, int viewport_height) {
  const render::Camera c = camera();
  const Eigen::Vector3d forward = (c.target - c.position).normalized();
  const Eigen::Vector3d right = forward.cross(up_).normalized();
  const Eigen::Vector3d view_up = right.cross(forward);
  // One pixel moves the target by the width of a pixel at the target's depth.
  const double per_pixel =
      2 * distance_ * std::tan(fov_ * M_PI / 360.0) / std::max(1.0, double(viewport_height));
  target_ += per_pixel * (-dx * right + dy * view_up);
}

void OrbitCamera::zoom(double wheel_steps) {
  distance_ = std::max(1e-4, distance_ * std::pow(0.85, wheel_steps));
}

render::Camera OrbitCamera::camera() const {
  render::Camera c;
  c.target = target_;
  c.up = up_;
  c.fov_degrees = fov_;
  const Eigen::Vector3d dir =
      std::cos(pitch_) * (std::cos(yaw_) * e1_ + std::sin(yaw_) * e2_) + std::sin(pitch_) * up_;
  c.position = target_ + distance_ * dir;
  return c;
}

}  // namespace upf::viewer
