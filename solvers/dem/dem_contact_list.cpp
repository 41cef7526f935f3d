#include "solvers/dem/dem_contact_list.h"

#include <utility>

namespace upf {

namespace {

DemCandidateSources candidate_sources(const Particles& p, const OwnedParticles& owned,
                                      const DemContactList::Sources& s) {
  return {p.position.data(),
          p.type.data(),
          p.material.data(),
          p.id.data(),
          p.body.data(),
          s.radius,
          owned.materials(),
          view_of(*s.grains),
          s.reactions ? view_of(*s.reactions) : NeighbourView{},
          s.boxes->data(),
          std::uint32_t(s.boxes->size()),
          s.skin,
          std::uint32_t(p.owned_size())};
}

// offsets[i + 1] += offsets[i]: counts into CSR offsets.
void scan_counts(std::vector<std::uint32_t>& offsets) {
  for (std::size_t i = 0; i + 1 < offsets.size(); ++i) offsets[i + 1] += offsets[i];
}

}  // namespace

void DemContactList::clear() {
  *this = DemContactList{};
}

void DemContactList::rebuild(const Particles& p, const OwnedParticles& owned, ParticleRange holders,
                             const Sources& sources, const CpuExecutor& exec) {
  const std::size_t n = p.size();
  // Last step's candidates become the history the new ones carry their springs from.
  std::swap(last_key_, key_);
  std::swap(last_xi_, xi_);
  const DemCandidateSources s = candidate_sources(p, owned, sources);

  offsets_.assign(n + 1, 0);
  exec.run_unshared(holders, DemCountCandidatesStage{s, offsets_.data()});
  scan_counts(offsets_);
  const std::size_t total = offsets_[n];
  partner_.resize(total);
  key_.resize(total);
  xi_.resize(total);
  force_.resize(total);
  partner_torque_.resize(total);
  partner_rolling_.resize(total);
  touching_.resize(total);
  exec.run_unshared(holders, DemFillCandidatesStage{s, offsets_.data(), partner_.data(),
                                                    key_.data(), xi_.data(), touching_.data()});
  carry_springs(p, holders, exec);
  build_reverse(s, n, exec);
}

void DemContactList::carry_springs(const Particles& p, ParticleRange holders,
                                   const CpuExecutor& exec) {
  // last_begin_by_id_ still describes last_key_ / last_xi_.
  exec.run_unshared(holders,
                    DemCarrySpringsStage{p.id.data(), offsets_.data(), key_.data(), xi_.data(),
                                         last_begin_by_id_.data(), last_count_by_id_.data(),
                                         std::uint32_t(last_count_by_id_.size()), last_key_.data(),
                                         last_xi_.data()});
  last_begin_by_id_.assign(p.id_bound(), 0);
  last_count_by_id_.assign(p.id_bound(), 0);
  exec.run_unshared(holders,
                    DemRecordByIdStage{p.id.data(), offsets_.data(), last_begin_by_id_.data(),
                                       last_count_by_id_.data()});
}

void DemContactList::build_reverse(const DemCandidateSources& s, std::size_t n,
                                   const CpuExecutor& exec) {
  const DemReverseCandidates reverse{s, offsets_.data(), partner_.data()};
  reverse_offsets_.assign(n + 1, 0);
  exec.run_unshared(all_particles(n), DemCountReverseStage{reverse, reverse_offsets_.data()});
  scan_counts(reverse_offsets_);
  reverse_.resize(reverse_offsets_[n]);
  exec.run_unshared(all_particles(n),
                    DemFillReverseStage{reverse, reverse_offsets_.data(), reverse_.data()});
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

void DemContactList::springs_into(DemSpringState& state) const {
  state.key = key_;
  state.xi = xi_;
  state.begin_by_id = last_begin_by_id_;
  state.count_by_id = last_count_by_id_;
}

void DemContactList::set_springs(const DemSpringState& state) {
  *this = DemContactList{};
  key_ = state.key;
  xi_ = state.xi;
  last_begin_by_id_ = state.begin_by_id;
  last_count_by_id_ = state.count_by_id;
}

}  // namespace upf
