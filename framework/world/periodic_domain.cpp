#include "framework/world/periodic_domain.h"

#include "framework/particles/particles.h"
#include "framework/world/coupling.h"

namespace upf {

PeriodicDomain::PeriodicDomain(const PeriodicBox& box, Real support_radius)
    : box_(box), reach_(periodic_image_reach(support_radius)) {}

void PeriodicDomain::distribute(Particles& particles, CouplingArrays& coupling) {
  particles_ = &particles;
  coupling_ = &coupling;
  drop_ghosts();
}

void PeriodicDomain::exchange(std::uint64_t) {
  Particles& p = *particles_;
  const std::size_t owned = p.owned_size();
  wrap_moving_particles(p, box_);
  sources_.clear();
  shifts_.clear();
  for (std::size_t i = 0; i < owned; ++i)
    box_.for_each_image_shift(p.position[i], reach_, [&](const Vec3& shift) {
      sources_.push_back(std::uint32_t(i));
      shifts_.push_back(shift);
    });
  scratch_.clear();
  p.pack(sources_.data(), sources_.size(), scratch_);
  p.append_packed(scratch_.data(), sources_.size());
  p.set_ghost_count(sources_.size());
  shift_images();
  traffic_.owned = owned;
  traffic_.ghosts = sources_.size();
  traffic_.halo_bytes = 0;
  traffic_.halo_refreshes = 0;
}

void wrap_moving_particles(Particles& particles, const PeriodicBox& box) {
  for (std::size_t i = 0; i < particles.owned_size(); ++i)
    if (particles.type[i] != ParticleType::Frozen) box.wrap(particles.position[i]);
}

void shift_ghost_positions(Particles& particles, const std::vector<Vec3>& shifts) {
  const std::size_t first = particles.owned_size();
  particles.for_each_position_array([&](std::vector<Vec3>& positions) {
    for (std::size_t k = 0; k < shifts.size(); ++k)
      positions[first + k] = PeriodicBox::shifted(positions[first + k], shifts[k]);
  });
}

void PeriodicDomain::shift_images() const {
  shift_ghost_positions(*particles_, shifts_);
}

void PeriodicDomain::refresh_ghosts() const {
  if (!particles_ || sources_.empty()) return;
  Particles& p = *particles_;
  const std::size_t first = p.owned_size();
  scratch_.clear();
  p.pack(sources_.data(), sources_.size(), scratch_);
  p.overwrite_packed(first, scratch_.data(), sources_.size());
  shift_images();
  // The coupling arrays a later solver reads (reactions, drag) travel with the images too.
  for (int a = 0; a < kCouplingArrayCount; ++a) {
    const auto array = CouplingArray(a);
    std::vector<Vec3>& values = (*coupling_)[array];
    if (!coupling_->active(array) || values.size() != p.size()) continue;
    for (std::size_t k = 0; k < sources_.size(); ++k) values[first + k] = values[sources_[k]];
  }
  traffic_.halo_bytes += scratch_.size();
  ++traffic_.halo_refreshes;
}

void PeriodicDomain::drop_ghosts() {
  particles_->truncate(particles_->owned_size());
  particles_->set_ghost_count(0);
  sources_.clear();
  shifts_.clear();
}

void PeriodicDomain::gather(const Particles& owned, Particles& whole) const {
  // In id order, as MpiDomain::gather: a periodic run's frames and checkpoints list the
  // particles alike on one rank and on many.
  whole = owned;
  whole.truncate(owned.owned_size());
  whole.set_ghost_count(0);
  whole.sort_by_id();
}

}  // namespace upf
