// The viewer's camera: it orbits a target point around the scene's up axis. Left-drag rotates,
// the scroll wheel zooms, right-drag pans; the result is a render::Camera for the ray tracer.
#pragma once

#include <Eigen/Core>

#include "render/camera.h"

namespace upf::viewer {

class OrbitCamera {
 public:
  explicit OrbitCamera(const render::Camera& start);
  // Mouse motion in pixels.
  void rotate(double dx, double dy);
  void pan(double dx, double dy, int viewport_height);
  void zoom(double wheel_steps);  // positive: closer
  render::Camera camera() const;

 private:
  Eigen::Vector3d target_, up_, e1_, e2_;  // e1, e2: horizontal axes
  double distance_, yaw_, pitch_, fov_;
};

}  // namespace upf::viewer
