#include "coupling/motion/prescribed_motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace upf {

namespace {

// The rotation by |w| about w / |w|; the identity for w = 0.
Eigen::Quaterniond rotation_vector_to_quaternion(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle == 0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle));
}

// The rotation vector (axis * angle, angle in [0, pi]) of the shortest arc equivalent to q.
Eigen::Vector3d quaternion_to_rotation_vector(Eigen::Quaterniond q) {
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // q and -q are the same rotation; take the short way
  const double sine = q.vec().norm();
  if (sine == 0) return Eigen::Vector3d::Zero();
  // atan2 keeps full precision for small angles, where acos(w) would not.
  return (2 * std::atan2(sine, q.w()) / sine) * q.vec();
}

bool same_rotation(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.coeffs() == b.coeffs() || a.coeffs() == -b.coeffs();
}

// The first key later than s: the segment containing s ends there (at a key's exact time, the
// segment that starts at that key).
template <class Keys>
auto first_key_after(const Keys& keys, double s) {
  return std::upper_bound(keys.begin(), keys.end(), s,
                          [](double time, const auto& key) { return time < key.first; });
}

}  // namespace

PrescribedMotion PrescribedMotion::constant(const Eigen::Vector3d& linear,
                                            const Eigen::Vector3d& angular) {
  if (!linear.allFinite() || !angular.allFinite())
    throw std::invalid_argument("PrescribedMotion::constant: velocities must be finite");
  PrescribedMotion motion;
  motion.constant_ = {linear, angular};
  return motion;
}

PrescribedMotion PrescribedMotion::keyframes(std::vector<std::pair<double, RigidPose>> keys,
                                             double loop_period) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("PrescribedMotion::keyframes: " + what);
  };
  if (keys.empty()) fail("at least one key is required");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    auto& [time, pose] = keys[i];
    if (!std::isfinite(time) || time < 0) fail("key times must be finite and not negative");
    if (i > 0 && !(time > keys[i - 1].first)) fail("key times must increase strictly");
    if (!pose.position.allFinite() || !pose.orientation.coeffs().allFinite() ||
        pose.orientation.norm() == 0)
      fail("key poses must be finite with a non-zero quaternion");
    pose.orientation.normalize();
  }
  if (!std::isfinite(loop_period) || loop_period < 0 ||
      (loop_period > 0 && loop_period < keys.back().first))
    fail("the loop period must be 0 (no loop) or at least the last key time");
  PrescribedMotion motion;
  motion.keyed_ = true;
  motion.keys_ = std::move(keys);
  motion.loop_period_ = loop_period;
  return motion;
}

PrescribedMotion PrescribedMotion::at_rest() {
  return constant({0, 0, 0}, {0, 0, 0});
}

double PrescribedMotion::keyed_time(double t) const {
  if (loop_period_ <= 0) return t;
  // fmod is exact; a negative remainder is shifted into [0, period), which rounding may turn into
  // the period itself for a tiny negative t: that is the start of the next period.
  double r = std::fmod(t, loop_period_);
  if (r < 0) r += loop_period_;
  return r >= loop_period_ ? 0 : r;
}

RigidPose PrescribedMotion::pose(double t) const {
  if (!keyed_) return {constant_.linear * t, rotation_vector_to_quaternion(constant_.angular * t)};
  const double s = keyed_time(t);
  const auto next = first_key_after(keys_, s);
  if (next == keys_.begin()) return keys_.front().second;
  if (next == keys_.end()) return keys_.back().second;
  const auto& [t0, p0] = *(next - 1);
  const auto& [t1, p1] = *next;
  const double f = (s - t0) / (t1 - t0);
  // Slerp written as (q1 q0^-1)^f q0, the same turn velocity() differentiates, so that the two
  // agree to rounding (Eigen's slerp goes through acos, which loses digits for small turns).
  const Eigen::Vector3d turn =
      quaternion_to_rotation_vector(p1.orientation * p0.orientation.conjugate());
  return {p0.position + f * (p1.position - p0.position),
          rotation_vector_to_quaternion(f * turn) * p0.orientation};
}

RigidVelocity PrescribedMotion::velocity(double t) const {
  if (!keyed_) return constant_;
  const double s = keyed_time(t);
  const auto next = first_key_after(keys_, s);
  if (next == keys_.begin() || next == keys_.end()) return {};  // holding still
  const auto& [t0, p0] = *(next - 1);
  const auto& [t1, p1] = *next;
  const double dt = t1 - t0;
  // slerp(q0, q1, f) = (q1 q0^-1)^f q0: a turn at a constant rate about the fixed world axis of
  // q1 q0^-1 (shortest arc).
  const Eigen::Vector3d turn =
      quaternion_to_rotation_vector(p1.orientation * p0.orientation.conjugate());
  return {(p1.position - p0.position) / dt, turn / dt};
}

bool PrescribedMotion::moves() const {
  if (!keyed_) return !constant_.linear.isZero(0) || !constant_.angular.isZero(0);
  const RigidPose& first = keys_.front().second;
  return std::any_of(keys_.begin() + 1, keys_.end(), [&](const Key& key) {
    return key.second.position != first.position ||
           !same_rotation(key.second.orientation, first.orientation);
  });
}

Eigen::Vector3d apply(const RigidPose& pose, const Eigen::Vector3d& pivot,
                      const Eigen::Vector3d& p) {
  return pose.position + pose.orientation * (p - pivot) + pivot;
}

Eigen::Vector3d point_velocity(const RigidVelocity& velocity, const RigidPose& pose,
                               const Eigen::Vector3d& pivot, const Eigen::Vector3d& p_world_now) {
  return velocity.linear + velocity.angular.cross(p_world_now - (pivot + pose.position));
}

}  // namespace upf
