// The per-particle work of body systems (body_system.h) as plain stages, so the CPU path and the
// device pipeline run the same code on their own arrays (DESIGN.md, "Stages, executors and
// backends"), with the same bits:
//
//   PlaceBodyParticlesStage  x = X + R r0, v = V + w x (x - X) for each particle of a moving body
//                            (rigid-fluid coupling of Akinci et al. 2012, ACM TOG 31(4));
//   RigidReactionWrench      a rigid particle's reaction force and its torque about the body's
//                            origin, in exact fixed point, so per-body sums do not depend on the
//                            order of additions (any thread count, any device);
//   SurfaceGuardStage        the penetration guard: a fluid particle inside a body's closed mesh
//                            is put back outside through the tangent plane of the nearest
//                            outer-layer sample and its velocity into the surface removed (direct
//                            boundary handling of Ihmsen et al. 2010, "Boundary handling and
//                            adaptive time-stepping for PCISPH", VRIPHYS); the removed momentum is
//                            a SurfaceHit for the body.
// C++17: nvcc builds it too.
#pragma once

#include <cmath>
#include <cstdint>

#include "framework/core/mesh_parity.h"
#include "framework/core/particle_type.h"
#include "framework/core/vec3d.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf {

// The fields of body particles: position and outward normal (outer-layer samples; zero on inner
// layers) in the body's frame.
inline constexpr const char* kBodyLocalPositionField = "body.local_position";
inline constexpr const char* kBodyLocalNormalField = "body.local_normal";

// The query of the neighbour lists over which solvers gather their reactions on bodies: the rigid
// particles, and where static or kinematic bodies exist, the frozen particles of a body too (their
// fluid force is reported like a free body's; the walls' frozen particles take none). 0 without
// body particles. Not for device code.
inline TypeMask body_reaction_query(const Particles& p) {
  bool frozen_bodies = false;
  for (std::size_t i = 0; i < p.size() && !frozen_bodies; ++i)
    frozen_bodies = p.type[i] == ParticleType::Frozen && p.body[i] != kNoBody;
  if (frozen_bodies) return kBoundaryMask | kOfBodiesOnly;
  return p.count(ParticleType::Rigid) > 0 ? mask_of(ParticleType::Rigid) : TypeMask(0);
}

// A body's frame: x = origin + rotation r0, v = velocity + angular_velocity x (x - origin).
struct BodyPose {
  Vec3d origin;
  Mat3d rotation;
  Vec3d velocity, angular_velocity;
  int moves = 0;  // 0: its particles stay where they are (static bodies)
};

struct PlaceBodyParticlesStage {
  const BodyPose* poses;  // per body id
  const BodyId* body;
  const Vec3* local;  // the particle's position in its body's frame
  Vec3* x;
  Vec3* v;
  // With free-slip boundaries (slip_normal.h): the normal in the body's frame, and the world
  // frame's it writes, for every body (static ones too: their world normals are not set
  // elsewhere). Null without.
  const Vec3* local_slip_normal = nullptr;
  Vec3* slip_normal = nullptr;

  UPF_HD void operator()(std::uint32_t i) const {
    const BodyId b = body[i];
    if (b == kNoBody) return;
    const BodyPose& f = poses[b];
    if (slip_normal) slip_normal[i] = to_real(f.rotation * to_double(local_slip_normal[i]));
    if (!f.moves) return;
    const Vec3d r = f.rotation * to_double(local[i]);
    x[i] = to_real(f.origin + r);
    v[i] = to_real(f.velocity + cross(f.angular_velocity, r));
  }
};

// Force (xyz) and torque (xyz) in units of 2^-32 N and N m. Sums wrap like unsigned integers and
// a value too large to hold marks the sum broken (it reads as NaN): exact, so any order of
// additions gives the same bits.
struct BodyWrench {
  std::int64_t units[6] = {0, 0, 0, 0, 0, 0};
  std::uint32_t broken = 0;

  static constexpr double kScale = 4294967296.0;  // 2^32
  static constexpr double kLimit = 9.2e18;        // below 2^63

  UPF_HD void add(int axis, double value) {
    const double scaled = value * kScale;
    if (!(scaled < kLimit && scaled > -kLimit)) {
      broken = 1;
      return;
    }
    units[axis] = std::int64_t(std::uint64_t(units[axis]) +
                               std::uint64_t(static_cast<std::int64_t>(nearbyint(scaled))));
  }
  double value(int axis) const { return broken ? std::nan("") : double(units[axis]) / kScale; }
};

struct BodyWrenchPlus {
  UPF_HD BodyWrench operator()(const BodyWrench& a, const BodyWrench& b) const {
    BodyWrench s;
    for (int k = 0; k < 6; ++k)
      s.units[k] = std::int64_t(std::uint64_t(a.units[k]) + std::uint64_t(b.units[k]));
    s.broken = a.broken | b.broken;
    return s;
  }
};

// Rigid particle i's reaction force[i] and its torque about its body's origin.
struct RigidReactionWrench {
  const Vec3* x;
  const Vec3* force;
  const BodyId* body;
  const Vec3d* origin;  // per body id

  UPF_HD BodyWrench operator()(std::uint32_t i) const {
    const Vec3d f = to_double(force[i]);
    const Vec3d tau = cross(to_double(x[i]) - origin[body[i]], f);
    BodyWrench w;
    w.add(0, f.x);
    w.add(1, f.y);
    w.add(2, f.z);
    w.add(3, tau.x);
    w.add(4, tau.y);
    w.add(5, tau.z);
    return w;
  }
};

// Momentum a fluid particle gave a body by being stopped at its surface.
struct SurfaceHit {
  std::uint32_t particle = 0;  // the fluid particle's stable id
  std::uint32_t body = 0;
  Vec3d point;    // where, world coordinates
  Vec3d impulse;  // N s, on the body
};

struct SurfaceGuardStage {
  Vec3* x;
  Vec3* v;
  const Real* mass;
  const ParticleType* type;
  const BodyId* body;
  const ParticleId* id;
  const Vec3* local;             // body-frame position of each boundary particle
  const Vec3* normal;            // body-frame outward normal of each outer-layer sample, else zero
  NeighbourView nearby;          // liquid -> boundary particles
  const BodyPose* poses;         // per body id, at the step's end
  const MeshParityView* meshes;  // per body id; no vertices: open, not guarded
  double layer_depth;            // how deep under the surface the outer sample layer lies, m
  double clearance;              // how far off the surface a particle is put back, m
  SurfaceHit* hits;              // per particle
  std::uint8_t* hit;             // per particle: 1 when moved

  UPF_HD void operator()(std::uint32_t i) const {
    hit[i] = 0;
    if (type[i] != ParticleType::Liquid) return;
    const Vec3d xi = to_double(x[i]);
    // The nearest outer-layer sample of a guarded body, where the bodies stand at the step's end
    // (ties go to the first in list order, which is fixed).
    bool found = false;
    double best = 0;
    std::uint32_t nearest = 0;
    Vec3d xb_best;
    for (std::uint32_t k = nearby.offsets[i]; k < nearby.offsets[i + 1]; ++k) {
      const std::uint32_t b = nearby.indices[k];
      if (body[b] == kNoBody || meshes[body[b]].vertices == nullptr) continue;
      if (normal[b].x == 0 && normal[b].y == 0 && normal[b].z == 0) continue;
      const BodyPose& f = poses[body[b]];
      const Vec3d xb = f.origin + f.rotation * to_double(local[b]);
      const double d2 = squared_norm(xi - xb);
      if (!found || d2 < best) {
        found = true;
        best = d2;
        nearest = b;
        xb_best = xb;
      }
    }
    if (!found) return;
    const BodyId owner = body[nearest];
    const BodyPose& f = poses[owner];
    if (!meshes[owner].contains(transpose_times(f.rotation, xi - f.origin))) return;
    const Vec3d n = f.rotation * to_double(normal[nearest]);
    const Vec3d surface = xb_best + layer_depth * n;
    // Out through the sample's tangent plane, to `clearance` beyond it.
    x[i] = to_real(xi + (clearance - dot(n, xi - surface)) * n);
    const Vec3d vb = f.velocity + cross(f.angular_velocity, surface - f.origin);
    const Vec3d vi = to_double(v[i]);
    const double approach = dot(n, vi - vb);  // < 0: moving into the body
    SurfaceHit s;
    s.particle = id[i];
    s.body = std::uint32_t(owner);
    s.point = surface;
    if (approach < 0) {
      v[i] = to_real(vi - approach * n);
      s.impulse = (double(mass[i]) * approach) * n;
    }
    hits[i] = s;
    hit[i] = 1;
  }
};

}  // namespace upf
