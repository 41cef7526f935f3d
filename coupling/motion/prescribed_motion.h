// Prescribed (kinematic) motion of a frozen boundary made from a mesh: a paddle pushed back and
// forth, a mixer turning at a constant rate. The motion is given, not computed: the fluid does
// not push back.
//
// A motion is a rigid pose as a function of time, relative to where the scene placed the mesh
// (mesh_transform.h): pose(t) is a displacement, not an absolute placement. A world point p of
// the placed mesh is at
//
//   x(t) = pose(t).position + pose(t).orientation * (p - pivot) + pivot
//
// The caller rotates about a pivot it chooses, e.g. the mesh's centroid or an explicit `pivot`
// from the scene; the motion itself knows no geometry. See apply() and point_velocity().
//
// Two kinds:
// - constant(v, w): the frame origin moves at v, the body turns at w (rad/s, world axes) about
//   its own origin: pose(t) = { v t, exp(w t) }, the rotation by |w| t about w / |w|.
// - keyframes: poses at increasing times; position linearly interpolated, orientation by slerp
//   (shortest arc), so each segment is a constant linear velocity plus a constant rotation about
//   a fixed world axis. Before the first key the body holds the first pose, after the last it
//   holds the last. With a loop period the keyed motion repeats: time is taken modulo the period
//   (the body holds the last pose from the last key to the end of the period, then jumps back to
//   the first pose; make the last key equal the first for a smooth loop).
//
// velocity(t) is the velocity for a step that starts at t: exact for constant motion, and for
// keyframes the (constant) velocity of the segment containing t, so that a step that ends on a
// key does not see the next segment's velocity early. Integrating it over a segment lands exactly
// on the next key.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <utility>
#include <vector>

namespace upf {

// World pose of a body frame.
struct RigidPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // where the body frame's origin is, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct RigidVelocity {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // of the frame origin, m/s
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // rad/s, world axes
};

class PrescribedMotion {
 public:
  // Constant velocities: the frame origin moves at `linear` (m/s); the body rotates at `angular`
  // (rad/s, world axes) about its own origin. Throws std::invalid_argument when not finite.
  static PrescribedMotion constant(const Eigen::Vector3d& linear, const Eigen::Vector3d& angular);
  // Keyed displacements (time in seconds, strictly increasing, at least one key, none negative;
  // the orientations need not be normalised). `loop_period` > 0 repeats the keyed motion with
  // that period, which must be at least the last key's time; 0: no loop. Throws
  // std::invalid_argument otherwise (scene files are checked by read_prescribed_motion first).
  static PrescribedMotion keyframes(std::vector<std::pair<double, RigidPose>> keys,
                                    double loop_period = 0);
  // Stays where the scene put it.
  static PrescribedMotion at_rest();

  // The displacement at time t from the initial placement. pose(0) is the identity for
  // constant(); for keyframes it is the first key's pose when that key is at 0 (key
  // {t: 0, position: [0, 0, 0]} means "where the scene put it").
  RigidPose pose(double t) const;
  // The velocity for a step starting at t; for keyframes that of the segment containing t (at an
  // exact key time, the segment that starts there), zero outside the keyed interval.
  RigidVelocity velocity(double t) const;
  // Whether pose(t) changes with t. A motion that does not move may still be a fixed
  // displacement (a single key away from the origin): apply pose(0) once.
  bool moves() const;

 private:
  using Key = std::pair<double, RigidPose>;
  PrescribedMotion() = default;
  // Time within the keyed pattern: t itself, or t modulo the loop period.
  double keyed_time(double t) const;

  bool keyed_ = false;
  RigidVelocity constant_;  // constant(): the velocities
  std::vector<Key> keys_;   // keyframes(): normalised orientations
  double loop_period_ = 0;
};

// Where the placed mesh's world point p is after the displacement `pose`, rotating about `pivot`
// (world, in the placed position): pose.position + pose.orientation * (p - pivot) + pivot.
Eigen::Vector3d apply(const RigidPose& pose, const Eigen::Vector3d& pivot,
                      const Eigen::Vector3d& p);

// Velocity of the body point now at `p_world_now` while the body is at `pose` and moves at
// `velocity`: linear + angular x (p_world_now - (pivot + pose.position)), since the pivot is
// carried to pivot + pose.position.
Eigen::Vector3d point_velocity(const RigidVelocity& velocity, const RigidPose& pose,
                               const Eigen::Vector3d& pivot, const Eigen::Vector3d& p_world_now);

}  // namespace upf
