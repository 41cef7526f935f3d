#include "coupling/bodies/penetration_guard.h"

#include <algorithm>
#include <cstring>

#include "framework/world/world.h"

namespace upf {

void PenetrationGuard::request(World& world) {
  list_ = world.request_neighbours(kLiquidMask, kBoundaryMask);
}

const std::vector<SurfaceHit>& PenetrationGuard::apply(
    World& world, const std::vector<BodyPose>& poses,
    const std::vector<const MeshParityData*>& meshes) {
  hits_.clear();
  if (list_ < 0) return hits_;
  if (DevicePipeline* device = world.device()) {
    device->guard_body_surfaces(poses, meshes, layer_depth_, clearance_, kBodyLocalPositionField,
                                kBodyLocalNormalField, hits_);
    return hits_;
  }
  Particles& p = world.particles();
  const std::vector<Vec3>* local = p.find_vector(kBodyLocalPositionField);
  const std::vector<Vec3>* normal = p.find_vector(kBodyLocalNormalField);
  if (!local || !normal) return hits_;
  std::vector<MeshParityView> views(meshes.size());
  for (std::size_t b = 0; b < meshes.size(); ++b)
    if (meshes[b]) views[b] = host_view(*meshes[b]);
  per_particle_.resize(p.size());
  hit_.resize(p.size());
  world.executor().run(
      all_particles(p.size()),
      SurfaceGuardStage{p.position.data(), p.velocity.data(), p.mass.data(), p.type.data(),
                        p.body.data(), p.id.data(), local->data(), normal->data(),
                        view_of(world.neighbours(list_)), poses.data(), views.data(), layer_depth_,
                        clearance_, per_particle_.data(), hit_.data()});
  for (std::size_t i = 0; i < p.owned_size(); ++i)
    if (hit_[i]) hits_.push_back(per_particle_[i]);
  // Across ranks every rank applies every rank's hits to its copy of the bodies.
  if (const ParticleDomain* domain = world.domain()) {
    std::vector<std::uint8_t> mine(hits_.size() * sizeof(SurfaceHit));
    if (!mine.empty()) std::memcpy(mine.data(), hits_.data(), mine.size());
    const std::vector<std::uint8_t> all = domain->all_gather(mine);
    hits_.resize(all.size() / sizeof(SurfaceHit));
    if (!all.empty()) std::memcpy(static_cast<void*>(hits_.data()), all.data(), all.size());
  }
  std::sort(hits_.begin(), hits_.end(),
            [](const SurfaceHit& a, const SurfaceHit& b) { return a.particle < b.particle; });
  return hits_;
}

}  // namespace upf
