// DemContactList (dem_contact_list.h) in a device pipeline: the same candidates, springs carried
// over by the same stable keys, and the same reverse index, built by the same stages
// (dem_contact_stages.h) with integer scans, so the list equals the CPU's entry for entry.
#pragma once

#include <cstddef>
#include <cstdint>

#include <thrust/copy.h>
#include <thrust/fill.h>
#include <thrust/scan.h>

#include "device/device_primitives.h"
#include "solvers/dem/dem_contact_stages.h"
#include "solvers/dem/dem_spring_state.h"
#include "solvers/dem/dem_views.h"

namespace upf::device {

template <class Backend>
class DeviceDemContacts {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  // The candidates of this world step for the grains in `owned` of n particles; springs carry
  // over from the last step's by the holder's id (ids below id_bound).
  void rebuild(const DemCandidateSources& s, ParticleRange owned, std::size_t n,
               ParticleId id_bound, const ParticleId* id) {
    last_key_.swap(key_);
    last_xi_.swap(xi_);
    counts_into_offsets(owned, DemCountCandidatesStage{s, nullptr}, n, offsets_);
    const std::size_t total = std::size_t(offsets_[n]);
    partner_.resize(total);
    key_.resize(total);
    xi_.resize(total);
    force_.resize(total);
    partner_torque_.resize(total);
    partner_rolling_.resize(total);
    touching_.resize(total);
    run<Backend>(
        owned, DemFillCandidatesStage{s, raw<std::uint32_t>(offsets_), raw<std::uint32_t>(partner_),
                                      raw<std::uint32_t>(key_), raw<Vec3>(xi_),
                                      raw<std::uint8_t>(touching_)});
    // Springs from the last step's candidates (last_begin_by_id_ still describes last_key_).
    run<Backend>(owned,
                 DemCarrySpringsStage{id, raw<std::uint32_t>(offsets_), raw<std::uint32_t>(key_),
                                      raw<Vec3>(xi_), raw<std::uint32_t>(last_begin_by_id_),
                                      raw<std::uint32_t>(last_count_by_id_),
                                      std::uint32_t(last_count_by_id_.size()),
                                      raw<std::uint32_t>(last_key_), raw<Vec3>(last_xi_)});
    zeroed(last_begin_by_id_, id_bound);
    zeroed(last_count_by_id_, id_bound);
    run<Backend>(owned, DemRecordByIdStage{id, raw<std::uint32_t>(offsets_),
                                           raw<std::uint32_t>(last_begin_by_id_),
                                           raw<std::uint32_t>(last_count_by_id_)});
    // The reverse index, over every particle.
    const DemReverseCandidates reverse{s, raw<std::uint32_t>(offsets_),
                                       raw<std::uint32_t>(partner_)};
    counts_into_offsets(all_particles(n), DemCountReverseStage{reverse, nullptr}, n,
                        reverse_offsets_);
    reverse_.resize(std::size_t(reverse_offsets_[n]));
    run<Backend>(all_particles(n),
                 DemFillReverseStage{reverse, raw<std::uint32_t>(reverse_offsets_),
                                     raw<std::uint32_t>(reverse_)});
  }

  DemContactView view() {
    return {raw<std::uint32_t>(offsets_),
            raw<std::uint32_t>(partner_),
            raw<Vec3>(xi_),
            raw<Vec3>(force_),
            raw<Vec3>(partner_torque_),
            raw<Vec3>(partner_rolling_),
            raw<std::uint8_t>(touching_),
            raw<std::uint32_t>(reverse_offsets_),
            raw<std::uint32_t>(reverse_)};
  }

  // The springs between steps, as the host's DemContactList keeps them.
  void springs_into(DemSpringState& state) const {
    copy_to_host(state.key, key_);
    copy_to_host(state.xi, xi_);
    copy_to_host(state.begin_by_id, last_begin_by_id_);
    copy_to_host(state.count_by_id, last_count_by_id_);
  }
  void set_springs(const DemSpringState& state) {
    copy_to_device(key_, state.key);
    copy_to_device(xi_, state.xi);
    copy_to_device(last_begin_by_id_, state.begin_by_id);
    copy_to_device(last_count_by_id_, state.count_by_id);
  }

  std::size_t bytes() const {
    return bytes_of(offsets_) + bytes_of(partner_) + bytes_of(key_) + bytes_of(xi_) +
           bytes_of(force_) + bytes_of(partner_torque_) + bytes_of(partner_rolling_) +
           bytes_of(touching_) + bytes_of(reverse_offsets_) + bytes_of(reverse_) +
           bytes_of(last_begin_by_id_) + bytes_of(last_count_by_id_) + bytes_of(last_key_) +
           bytes_of(last_xi_);
  }

 private:
  // offsets = [0, counts...] scanned: `Count` writes counts[i + 1] for each i of `range`.
  template <class Count>
  static void counts_into_offsets(ParticleRange range, Count count, std::size_t n,
                                  vector<std::uint32_t>& offsets) {
    zeroed(offsets, n + 1);
    count.counts = raw<std::uint32_t>(offsets);
    run<Backend>(range, count);
    thrust::inclusive_scan(Backend::policy(), offsets.begin(), offsets.end(), offsets.begin());
  }
  template <class T>
  static void zeroed(vector<T>& v, std::size_t n) {
    v.resize(n);
    thrust::fill(Backend::policy(), v.begin(), v.end(), T{});
  }

  vector<std::uint32_t> offsets_, partner_, key_;
  vector<Vec3> xi_, force_, partner_torque_, partner_rolling_;
  vector<std::uint8_t> touching_;
  vector<std::uint32_t> reverse_offsets_, reverse_;
  vector<std::uint32_t> last_begin_by_id_, last_count_by_id_, last_key_;
  vector<Vec3> last_xi_;
};

}  // namespace upf::device
