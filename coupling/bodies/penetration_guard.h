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
// are not guarded. The per-particle work is SurfaceGuardStage (body_particle_stages.h), on the
// CPU executor or, when the world steps on a device, there.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/mesh_parity.h"
#include "framework/world/body_particle_stages.h"

namespace upf {

class World;

class PenetrationGuard {
 public:
  // `layer_depth`: how deep under the surface the outer sample layer lies, m; `clearance`: how
  // far off the surface a particle is put back, m.
  PenetrationGuard(double layer_depth, double clearance)
      : layer_depth_(layer_depth), clearance_(clearance) {}

  // Asks the world for the fluid -> boundary neighbour list (shared with the fluid solvers).
  void request(World& world);

  // Moves the fluid particles that are inside a body, given each body's end-of-step pose and
  // its mesh in the body frame (null: open, not guarded), and returns the impulses on the bodies
  // in the order of the particles' stable ids (the same for any thread count, any order of the
  // particles in memory, and on the device).
  const std::vector<SurfaceHit>& apply(World& world, const std::vector<BodyPose>& poses,
                                       const std::vector<const MeshParityData*>& meshes);

  // Fluid particles moved by the last apply().
  std::size_t corrected() const { return hits_.size(); }

 private:
  double layer_depth_, clearance_;
  int list_ = -1;
  std::vector<SurfaceHit> per_particle_;
  std::vector<std::uint8_t> hit_;
  std::vector<SurfaceHit> hits_;
};

}  // namespace upf
