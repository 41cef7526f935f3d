// Conversions between the particle arrays' Vec3 and host geometry's Eigen vectors.
#pragma once

#include <Eigen/Core>

#include "framework/core/vec3.h"

namespace upf {

inline Vec3 to_vec3(const Eigen::Vector3d& v) {
  return {Real(v.x()), Real(v.y()), Real(v.z())};
}

inline Eigen::Vector3d to_eigen(const Vec3& v) {
  return {double(v.x), double(v.y), double(v.z)};
}

}  // namespace upf
