#include "coupling/bodies/penetration_guard.h"

#include <algorithm>
#include <limits>

#include "framework/core/vec3_eigen.h"
#include "framework/world/world.h"

namespace upf {

void PenetrationGuard::request(World& world) {
  list_ = world.request_neighbours(kLiquidMask, kBoundaryMask);
}

const std::vector<SurfaceImpulse>& PenetrationGuard::apply(
    World& world, const std::vector<BodyFrame>& frames,
    const std::vector<const MeshInsideTest*>& meshes) {
  impulses_.clear();
  Particles& p = world.particles();
  const std::vector<Vec3>* local = p.find_vector("body.local_position");
  const std::vector<Vec3>* normal = p.find_vector(kBodyLocalNormalField);
  if (list_ < 0 || !local || !normal) return impulses_;
  const NeighbourList& list = world.neighbours(list_);
  per_particle_.resize(p.size());
  hit_.assign(p.size(), 0);

  Vec3* x = p.position.data();
  Vec3* v = p.velocity.data();
  const Real* mass = p.mass.data();
  const ParticleType* type = p.type.data();
  const BodyId* body = p.body.data();
  const Vec3* r0 = local->data();
  const Vec3* n0 = normal->data();
  world.executor().for_each_index(p.size(), [&](std::size_t i) {
    if (type[i] != ParticleType::Liquid) return;
    const Eigen::Vector3d xi = to_eigen(x[i]);
    // The nearest outer-layer sample of a guarded body, where the bodies stand at the step's end
    // (ties go to the first in list order, which is fixed).
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t nearest = 0;
    Eigen::Vector3d xb_best = Eigen::Vector3d::Zero();
    for (std::uint32_t k = list.offsets[i]; k < list.offsets[i + 1]; ++k) {
      const std::uint32_t b = list.indices[k];
      if (body[b] == kNoBody || !meshes[std::size_t(body[b])]) continue;
      if (n0[b].x == 0 && n0[b].y == 0 && n0[b].z == 0) continue;
      const BodyFrame& f = frames[std::size_t(body[b])];
      const Eigen::Vector3d xb = f.origin + f.rotation * to_eigen(r0[b]);
      const double d2 = (xi - xb).squaredNorm();
      if (d2 < best) {
        best = d2;
        nearest = b;
        xb_best = xb;
      }
    }
    if (best == std::numeric_limits<double>::infinity()) return;
    const std::size_t owner = std::size_t(body[nearest]);
    const BodyFrame& f = frames[owner];
    if (!meshes[owner]->contains(f.rotation.transpose() * (xi - f.origin))) return;
    const Eigen::Vector3d n = f.rotation * to_eigen(n0[nearest]);
    const Eigen::Vector3d surface = xb_best + layer_depth_ * n;
    // Out through the sample's tangent plane, to `clearance` beyond it.
    x[i] = to_vec3(xi + (clearance_ - n.dot(xi - surface)) * n);
    const Eigen::Vector3d vb = f.velocity + f.angular_velocity.cross(surface - f.origin);
    const Eigen::Vector3d vi = to_eigen(v[i]);
    const double approach = n.dot(vi - vb);  // < 0: moving into the body
    SurfaceImpulse& s = per_particle_[i];
    s.particle = p.id[i];
    s.body = std::uint32_t(owner);
    s.point = surface;
    s.impulse = Eigen::Vector3d::Zero();
    if (approach < 0) {
      v[i] = to_vec3(vi - approach * n);
      s.impulse = double(mass[i]) * approach * n;
    }
    hit_[i] = 1;
  });
  for (std::size_t i = 0; i < p.size(); ++i)
    if (hit_[i]) impulses_.push_back(per_particle_[i]);
  std::sort(impulses_.begin(), impulses_.end(),
            [](const SurfaceImpulse& a, const SurfaceImpulse& b) { return a.particle < b.particle; });
  return impulses_;
}

}  // namespace upf
