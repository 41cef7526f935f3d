#include "solvers/dem/dem_contact_history.h"

#include <utility>

namespace upf {

void DemContactHistory::reset(const Particles& particles) {
  row_.assign(particles.id_bound(), -1);
  std::int32_t rows = 0;
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.type[i] == ParticleType::Granular) row_[particles.id[i]] = rows++;
  old_.assign(std::size_t(rows) * kSlots, DemContactSlot{});
  new_ = old_;
  old_count_.assign(std::size_t(rows), 0);
  new_count_ = old_count_;
}

Vec3 DemContactHistory::old_xi(ParticleId id, std::uint32_t key) const {
  const std::size_t r = std::size_t(row_[id]);
  const DemContactSlot* s = &old_[r * kSlots];
  for (int k = 0; k < old_count_[r]; ++k)
    if (s[k].key == key) return s[k].xi;
  return {};
}

Vec3 DemContactHistory::new_force(ParticleId id, std::uint32_t key) const {
  const DemContactSlot* s = find_new(id, key);
  return s ? s->force : Vec3{};
}

const DemContactSlot* DemContactHistory::find_new(ParticleId id, std::uint32_t key) const {
  const std::size_t r = std::size_t(row_[id]);
  const DemContactSlot* s = &new_[r * kSlots];
  for (int k = 0; k < new_count_[r]; ++k)
    if (s[k].key == key) return &s[k];
  return nullptr;
}

bool DemContactHistory::record(ParticleId id, const DemContactSlot& slot) {
  const std::size_t r = std::size_t(row_[id]);
  std::uint8_t& n = new_count_[r];
  if (n >= kSlots) return false;
  new_[r * kSlots + n] = slot;
  ++n;
  return true;
}

void DemContactHistory::swap() {
  std::swap(old_, new_);
  std::swap(old_count_, new_count_);
}

}  // namespace upf
