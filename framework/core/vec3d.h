// Double-precision 3-vectors and 3x3 matrices for per-particle code that must run on a device and
// on the host with the same bits: body frames, where Eigen cannot go (no Eigen in device code).
// Every operation is written out in a fixed order, so both compilers round alike (given no
// contraction into fused multiply-adds: nvcc --fmad=false, -ffp-contract=off on the host).
#pragma once

#include "framework/core/real.h"
#include "framework/core/vec3.h"

namespace upf {

struct Vec3d {
  double x = 0, y = 0, z = 0;
};

UPF_HD constexpr Vec3d operator+(const Vec3d& a, const Vec3d& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
UPF_HD constexpr Vec3d operator-(const Vec3d& a, const Vec3d& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
UPF_HD constexpr Vec3d operator*(const Vec3d& a, double s) {
  return {a.x * s, a.y * s, a.z * s};
}
UPF_HD constexpr Vec3d operator*(double s, const Vec3d& a) {
  return {s * a.x, s * a.y, s * a.z};
}
UPF_HD constexpr double dot(const Vec3d& a, const Vec3d& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
UPF_HD constexpr Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
UPF_HD constexpr double squared_norm(const Vec3d& a) {
  return dot(a, a);
}
UPF_HD constexpr Vec3d to_double(const Vec3& a) {
  return {double(a.x), double(a.y), double(a.z)};
}
UPF_HD constexpr Vec3 to_real(const Vec3d& a) {
  return {Real(a.x), Real(a.y), Real(a.z)};
}

// Row-major: m[3 * row + column].
struct Mat3d {
  double m[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};

UPF_HD constexpr Vec3d operator*(const Mat3d& a, const Vec3d& v) {
  return {a.m[0] * v.x + a.m[1] * v.y + a.m[2] * v.z, a.m[3] * v.x + a.m[4] * v.y + a.m[5] * v.z,
          a.m[6] * v.x + a.m[7] * v.y + a.m[8] * v.z};
}
// a^T v: a rotation's inverse applied.
UPF_HD constexpr Vec3d transpose_times(const Mat3d& a, const Vec3d& v) {
  return {a.m[0] * v.x + a.m[3] * v.y + a.m[6] * v.z, a.m[1] * v.x + a.m[4] * v.y + a.m[7] * v.z,
          a.m[2] * v.x + a.m[5] * v.y + a.m[8] * v.z};
}

}  // namespace upf
