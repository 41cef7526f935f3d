#include "solvers/dem/dem_contact_list.h"

#include <utility>

namespace upf {

namespace {

// Building the list is bookkeeping on the host, like building neighbour lists, not a particle
// stage: it runs before the sub-steps, whose stages read the list through DemContactView.
template <class Body>
void for_each_owned(const CpuExecutor& exec, const OwnedParticles& owned, Body&& body) {
  exec.for_each_index(owned.size(), [&](std::size_t k) { body(owned[k]); });
}

// Calls emit(partner, key) for each candidate of grain i: container faces first (container and
// face order), then the neighbours it holds, in neighbour-list order.
template <class Holds, class Emit>
void for_each_candidate(const Particles& p, const DemContactList::Sources& s, std::uint32_t i,
                        Holds&& holds, Emit&& emit) {
  const Vec3& x = p.position[i];
  const Real reach = s.radius[i] + s.skin;
  const std::vector<ContainerBox>& boxes = *s.boxes;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const ContainerBox& box = boxes[b];
    bool near = true;
    for (int a = 0; a < 3; ++a)
      near = near && x[a] > box.min[a] - reach && x[a] < box.max[a] + reach;
    if (!near) continue;
    for (int face = 0; face < 6; ++face) {
      const int a = face / 2;
      const Real gap = face % 2 == 0 ? x[a] - box.min[a] : box.max[a] - x[a];
      if (gap < reach)
        emit(kDemWallPartner | std::uint32_t(b * 6 + std::size_t(face)), dem_wall_key(b, face));
    }
  }
  const NeighbourList& list = *s.grains;
  for (std::uint32_t k = list.offsets[i]; k < list.offsets[i + 1]; ++k) {
    const std::uint32_t j = list.indices[k];
    if (holds(i, j)) emit(j, std::uint32_t(p.id[j]));
  }
}

}  // namespace

bool DemContactList::holds(const Particles& p, const OwnedParticles& owned, std::uint32_t i,
                           std::uint32_t j) {
  if (p.type[j] == ParticleType::Granular) return p.id[j] > p.id[i] || !owned.owns(p.material[j]);
  return p.body[j] != kNoBody;
}

void DemContactList::clear() {
  *this = DemContactList{};
}

void DemContactList::rebuild(const Particles& p, const OwnedParticles& owned,
                             const Sources& sources, const CpuExecutor& exec) {
  const std::size_t n = p.size();
  // Last step's candidates become the history the new ones carry their springs from.
  std::swap(last_key_, key_);
  std::swap(last_xi_, xi_);
  const auto held = [&](std::uint32_t i, std::uint32_t j) { return holds(p, owned, i, j); };

  offsets_.assign(n + 1, 0);
  for_each_owned(exec, owned, [&](std::uint32_t i) {
    std::uint32_t count = 0;
    for_each_candidate(p, sources, i, held, [&](std::uint32_t, std::uint32_t) { ++count; });
    offsets_[i + 1] = count;
  });
  for (std::size_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  const std::size_t total = offsets_[n];
  partner_.resize(total);
  key_.resize(total);
  xi_.assign(total, Vec3{});
  force_.resize(total);
  partner_torque_.resize(total);
  partner_rolling_.resize(total);
  touching_.assign(total, 0);
  for_each_owned(exec, owned, [&](std::uint32_t i) {
    std::uint32_t k = offsets_[i];
    for_each_candidate(p, sources, i, held, [&](std::uint32_t partner, std::uint32_t key) {
      partner_[k] = partner;
      key_[k] = key;
      ++k;
    });
  });
  carry_springs(p, owned, exec);
  build_reverse(p, owned, sources, exec);
}

void DemContactList::carry_springs(const Particles& p, const OwnedParticles& owned,
                                   const CpuExecutor& exec) {
  // last_begin_by_id_ still describes last_key_ / last_xi_.
  for_each_owned(exec, owned, [&](std::uint32_t i) {
    const ParticleId me = p.id[i];
    if (me >= last_count_by_id_.size() || last_count_by_id_[me] == 0) return;
    const std::uint32_t first = last_begin_by_id_[me], last = first + last_count_by_id_[me];
    for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
      for (std::uint32_t o = first; o < last; ++o)
        if (last_key_[o] == key_[k]) {
          xi_[k] = last_xi_[o];
          break;
        }
  });
  last_begin_by_id_.assign(p.id_bound(), 0);
  last_count_by_id_.assign(p.id_bound(), 0);
  for_each_owned(exec, owned, [&](std::uint32_t i) {
    last_begin_by_id_[p.id[i]] = offsets_[i];
    last_count_by_id_[p.id[i]] = offsets_[i + 1] - offsets_[i];
  });
}

void DemContactList::build_reverse(const Particles& p, const OwnedParticles& owned,
                                   const Sources& sources, const CpuExecutor& exec) {
  const std::size_t n = p.size();
  // Calls emit(k) for each candidate with partner j, in j's neighbour-list order.
  const auto for_each_reverse = [&](std::size_t j, auto&& emit) {
    const NeighbourList* list = nullptr;
    if (p.type[j] == ParticleType::Granular && owned.owns(p.material[j]))
      list = sources.grains;
    else if (p.type[j] == ParticleType::Rigid && sources.reactions)
      list = sources.reactions;
    if (!list) return;
    for (std::uint32_t r = list->offsets[j]; r < list->offsets[j + 1]; ++r) {
      const std::uint32_t i = list->indices[r];
      if (p.type[i] != ParticleType::Granular || !owned.owns(p.material[i])) continue;
      for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
        if (partner_[k] == j) {
          emit(k);
          break;
        }
    }
  };
  reverse_offsets_.assign(n + 1, 0);
  exec.for_each_index(n, [&](std::size_t j) {
    std::uint32_t count = 0;
    for_each_reverse(j, [&](std::uint32_t) { ++count; });
    reverse_offsets_[j + 1] = count;
  });
  for (std::size_t j = 0; j < n; ++j) reverse_offsets_[j + 1] += reverse_offsets_[j];
  reverse_.resize(reverse_offsets_[n]);
  exec.for_each_index(n, [&](std::size_t j) {
    std::uint32_t r = reverse_offsets_[j];
    for_each_reverse(j, [&](std::uint32_t k) { reverse_[r++] = k; });
  });
}

void DemContactList::save_state(StateWriter& out) const {
  out.put_vector(key_);
  out.put_vector(xi_);
  out.put_vector(last_begin_by_id_);
  out.put_vector(last_count_by_id_);
}

void DemContactList::restore_state(StateReader& in) {
  *this = DemContactList{};
  in.get_vector(key_);
  in.get_vector(xi_);
  in.get_vector(last_begin_by_id_);
  in.get_vector(last_count_by_id_);
  bool fits = xi_.size() == key_.size() && last_begin_by_id_.size() == last_count_by_id_.size();
  for (std::size_t id = 0; fits && id < last_begin_by_id_.size(); ++id)
    fits = std::uint64_t(last_begin_by_id_[id]) + last_count_by_id_[id] <= key_.size();
  in.expect(fits, "the DEM contact springs");
}

}  // namespace upf
