// The last line of defence between a fluid and a body: after the fluid has moved, a fluid
// particle whose centre is inside a body's mesh is put back outside, a small distance off the
// surface along its normal, and its velocity into the surface is removed. The removed
// momentum goes to the body as an impulse at the contact point, so the pair still conserves
// momentum. This is the direct boundary collision handling of Ihmsen, Akinci, Gissler & Teschner
// 2010, "Boundary handling and adaptive time-stepping for PCISPH" (VRIPHYS), used with the
// Akinci boundary forces: the forces do the work, the guard catches the particles that a fast
// body (a slam at 1 m/s, a paddle) would otherwise push through its two-layer surface.
//
// "Inside" is exact: ray parity against the body's closed mesh in the body frame. The way out is
// through the tangent plane of the nearest outer-layer sample, which carries the mesh's outward
// normal (inner-layer samples carry none); samples are at most half a spacing apart, so the
// plane is a good local stand-in for the mesh. Open meshes (static obstacles) have no inside and
// are not guarded.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "coupling/mesh/mesh_inside_test.h"

namespace upf {

class World;

inline constexpr const char* kBodyLocalNormalField = "body.local_normal";

// A body's frame at the end of the step: x = origin + rotation r0, v = velocity + w x (x - origin).
struct BodyFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
};

// Momentum a fluid particle gave a body by being stopped at its surface.
struct SurfaceImpulse {
  std::uint32_t particle = 0;  // the fluid particle's stable id
  std::uint32_t body = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // where, world coordinates
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  // N s, on the body
};

class PenetrationGuard {
 public:
  // `layer_depth`: how deep under the surface the outer sample layer lies, m; `clearance`: how
  // far off the surface a particle is put back, m.
  PenetrationGuard(double layer_depth, double clearance)
      : layer_depth_(layer_depth), clearance_(clearance) {}

  // Asks the world for the fluid -> boundary neighbour list (shared with the fluid solvers).
  void request(World& world);

  // Moves the fluid particles that are inside a body, given each body's end-of-step frame and
  // its mesh in the body frame (null: open, not guarded), and returns the impulses on the bodies
  // in the order of the particles' stable ids (the same for any thread count and any order of
  // the particles in memory).
  const std::vector<SurfaceImpulse>& apply(World& world, const std::vector<BodyFrame>& frames,
                                           const std::vector<const MeshInsideTest*>& meshes);

  // Fluid particles moved by the last apply().
  std::size_t corrected() const { return impulses_.size(); }

 private:
  double layer_depth_, clearance_;
  int list_ = -1;
  std::vector<SurfaceImpulse> per_particle_;
  std::vector<std::uint8_t> hit_;
  std::vector<SurfaceImpulse> impulses_;
};

}  // namespace upf
