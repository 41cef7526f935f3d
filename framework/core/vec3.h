// A plain 3-vector for particle arrays. Plain old data so that nvcc and OpenMP loops see
// through it; host-side geometry (scene boxes, meshes) uses Eigen instead.
#pragma once

#include <cmath>

#include "framework/core/real.h"

namespace upf {

struct Vec3 {
  Real x = 0, y = 0, z = 0;

  UPF_HD constexpr Real operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  UPF_HD constexpr Real& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }

  UPF_HD constexpr Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  UPF_HD constexpr Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  UPF_HD constexpr Vec3& operator*=(Real s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
};

UPF_HD constexpr Vec3 operator+(Vec3 a, const Vec3& b) {
  return a += b;
}
UPF_HD constexpr Vec3 operator-(Vec3 a, const Vec3& b) {
  return a -= b;
}
UPF_HD constexpr Vec3 operator-(const Vec3& a) {
  return {-a.x, -a.y, -a.z};
}
UPF_HD constexpr Vec3 operator*(Vec3 a, Real s) {
  return a *= s;
}
UPF_HD constexpr Vec3 operator*(Real s, Vec3 a) {
  return a *= s;
}
UPF_HD constexpr Vec3 operator/(const Vec3& a, Real s) {
  return {a.x / s, a.y / s, a.z / s};
}
UPF_HD constexpr bool operator==(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

UPF_HD constexpr Real dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
UPF_HD constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
UPF_HD constexpr Real squared_norm(const Vec3& a) {
  return dot(a, a);
}
UPF_HD inline Real norm(const Vec3& a) {
  return std::sqrt(squared_norm(a));
}
UPF_HD inline bool is_finite(const Vec3& a) {
#if defined(__CUDA_ARCH__)
  // libstdc++'s std::isfinite is a constexpr host function; CUDA's own isfinite runs on devices.
  return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
#else
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
#endif
}

}  // namespace upf
