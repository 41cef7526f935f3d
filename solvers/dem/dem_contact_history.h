// The tangential springs of the contacts, kept from one sub-step to the next: each grain holds up
// to kSlots contacts (partner key, displacement xi, last force and rolling torque), found by the
// partner's stable id so that reordering the particles loses nothing. A pair of grains is kept
// by the grain with the lower id only; the other reads the force back from it. Two buffers: a
// sub-step reads the old and writes the new, so grains never see each other's half-updated state.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/vec3.h"
#include "framework/particles/particles.h"

namespace upf {

struct DemContactSlot {
  std::uint32_t key = 0;  // partner id, or a wall key (dem_wall_key)
  Vec3 xi;                // tangential displacement, m
  Vec3 force;             // on the grain from this partner in the last sub-step, N
  Vec3 rolling;           // rolling-resistance torque on the grain, N m
};

// Wall faces are partners too: container c, face f (0..5) gets a key above every particle id.
inline constexpr std::uint32_t dem_wall_key(std::size_t container, int face) {
  return 0xFFFFFFFFu - std::uint32_t(container * 6 + std::size_t(face));
}

class DemContactHistory {
 public:
  static constexpr int kSlots = 24;

  // Gives every grain (by id) its slots.
  void reset(const Particles& particles);

  bool has(ParticleId id) const { return id < row_.size() && row_[id] >= 0; }
  // The old displacement of grain `id` with partner `key` (zero when they were not touching).
  Vec3 old_xi(ParticleId id, std::uint32_t key) const;
  // The force grain `id` felt from `key` in the sub-step just computed (zero if none).
  Vec3 new_force(ParticleId id, std::uint32_t key) const;
  // Grain `id`'s contact with `key` in the sub-step just computed, or null.
  const DemContactSlot* find_new(ParticleId id, std::uint32_t key) const;
  // Starts grain `id`'s new contact list; record() appends (false when the slots are full).
  void begin(ParticleId id) { new_count_[std::size_t(row_[id])] = 0; }
  bool record(ParticleId id, const DemContactSlot& slot);
  // The new lists become the old.
  void swap();

 private:
  std::vector<std::int32_t> row_;  // by id: the grain's row, -1 for other particles
  std::vector<DemContactSlot> old_, new_;
  std::vector<std::uint8_t> old_count_, new_count_;
};

}  // namespace upf
