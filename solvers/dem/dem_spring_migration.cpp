// DemContactList on a world split over MPI ranks: the springs follow the particles that migrate,
// in the way LAMMPS's fix neigh/history carries a pair's shear history with its atoms, and a
// checkpoint merges every rank's springs.
//
// A pair's spring is the same bits on every rank that computes it (both compute it from the same
// ghost copies, in the one-rank operand order, from the same spring), so merging keeps any one of
// equal (holder, key) records.
#include <algorithm>
#include <cstring>
#include <utility>

#include "solvers/dem/dem_contact_list.h"

namespace upf {

namespace {

void append_record(std::vector<std::uint8_t>& out, const DemSpringRecord& r) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&r);
  out.insert(out.end(), bytes, bytes + sizeof r);
}

void append_records(const std::vector<std::uint8_t>& bytes, std::vector<DemSpringRecord>& out) {
  const std::size_t n = bytes.size() / sizeof(DemSpringRecord);
  const std::size_t at = out.size();
  out.resize(at + n);
  if (n > 0) std::memcpy(out.data() + at, bytes.data(), n * sizeof(DemSpringRecord));
}

// Sorted by (holder, key), one record per pair.
void merge(std::vector<DemSpringRecord>& records) {
  auto pair_of = [](const DemSpringRecord& r) { return std::pair(r.holder, r.key); };
  std::stable_sort(records.begin(), records.end(),
                   [&](const auto& a, const auto& b) { return pair_of(a) < pair_of(b); });
  records.erase(std::unique(records.begin(), records.end(),
                            [&](const auto& a, const auto& b) { return pair_of(a) == pair_of(b); }),
                records.end());
}

// The rank each departed particle went to, by stable id; -1 for one that stayed.
class Destinations {
 public:
  explicit Destinations(const std::vector<std::vector<std::uint32_t>>& departed) {
    for (std::size_t r = 0; r < departed.size(); ++r)
      for (std::uint32_t id : departed[r]) to_.emplace_back(id, int(r));
    std::sort(to_.begin(), to_.end());
  }
  bool empty() const { return to_.empty(); }
  int operator()(std::uint32_t id) const {
    const auto it = std::lower_bound(to_.begin(), to_.end(), std::pair(id, -1));
    return it != to_.end() && it->first == id ? it->second : -1;
  }

 private:
  std::vector<std::pair<std::uint32_t, int>> to_;
};

}  // namespace

std::vector<DemSpringRecord> DemContactList::records() const {
  std::vector<DemSpringRecord> out;
  out.reserve(key_.size());
  for (std::uint32_t id = 0; id < std::uint32_t(last_begin_by_id_.size()); ++id) {
    const std::uint32_t first = last_begin_by_id_[id];
    for (std::uint32_t o = first; o < first + last_count_by_id_[id]; ++o)
      out.push_back({id, key_[o], xi_[o]});
  }
  return out;
}

void DemContactList::set_records(std::vector<DemSpringRecord> records) {
  merge(records);
  key_.resize(records.size());
  xi_.resize(records.size());
  const std::uint32_t ids = records.empty() ? 0 : records.back().holder + 1;
  last_begin_by_id_.assign(std::max<std::size_t>(ids, last_begin_by_id_.size()), 0);
  last_count_by_id_.assign(last_begin_by_id_.size(), 0);
  for (std::size_t o = 0; o < records.size(); ++o) {
    const DemSpringRecord& r = records[o];
    if (last_count_by_id_[r.holder]++ == 0) last_begin_by_id_[r.holder] = std::uint32_t(o);
    key_[o] = r.key;
    xi_[o] = r.xi;
  }
}

void DemContactList::follow_migration(const ParticleDomain& domain) {
  const Destinations to(domain.departed());
  std::vector<std::vector<std::uint8_t>> sends(domain.departed().size());
  // The records are listed only when something moved: most steps, on most ranks, nothing does.
  std::vector<DemSpringRecord> mine;
  if (!to.empty()) {
    mine = records();
    for (const DemSpringRecord& r : mine) {
      // The holder's new rank computes the pair; so does the partner's (wall keys are no ids).
      const int holder_rank = to(r.holder);
      const int partner_rank = to(r.key);
      if (holder_rank >= 0) append_record(sends[std::size_t(holder_rank)], r);
      if (partner_rank >= 0 && partner_rank != holder_rank)
        append_record(sends[std::size_t(partner_rank)], r);
    }
  }
  // Every rank takes part, whether or not it sends anything.
  const std::vector<std::uint8_t> arrived = domain.exchange_bytes(sends);
  if (arrived.empty()) return;
  if (to.empty()) mine = records();
  append_records(arrived, mine);
  set_records(std::move(mine));
}

void DemContactList::save_gathered(StateWriter& out, const ParticleDomain& domain) const {
  std::vector<std::uint8_t> mine;
  for (const DemSpringRecord& r : records()) append_record(mine, r);
  std::vector<DemSpringRecord> all;
  append_records(domain.all_gather(mine), all);
  DemContactList whole;
  whole.set_records(std::move(all));
  whole.save_state(out);
}

}  // namespace upf
