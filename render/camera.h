// A pinhole camera: where it stands, what it looks at, which way is up, and its vertical field
// of view. Pixel (column, row) maps to a primary ray through the pixel's centre.
#pragma once

#include <Eigen/Core>

namespace upf::render {

struct Camera {
  Eigen::Vector3d position{2, 1.5, 3};
  Eigen::Vector3d target{0, 0, 0};
  Eigen::Vector3d up{0, 1, 0};
  double fov_degrees = 40;
};

struct Ray {
  Eigen::Vector3f origin;
  Eigen::Vector3f direction;  // unit length
};

// Precomputed image-plane axes for one image size.
class CameraRays {
 public:
  CameraRays(const Camera& camera, int width, int height);
  // (x, y) in pixels from the top-left corner; (0.5, 0.5) is the first pixel's centre.
  Ray through(double x, double y) const;
  Eigen::Vector3f forward() const { return forward_.cast<float>(); }
  Eigen::Vector3f right() const { return right_.cast<float>(); }
  Eigen::Vector3f up() const { return up_.cast<float>(); }

 private:
  Eigen::Vector3d origin_, forward_, right_, up_;
  double half_width_, half_height_;  // of the image plane at distance 1
  int width_, height_;
};

// A camera that shows the box [lo, hi] whole, seen from the front-right and above, with `up` as
// the vertical (the direction opposite to gravity).
Camera frame_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector3d& up,
                 double aspect);

}  // namespace upf::render
