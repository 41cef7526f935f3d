#include "framework/mpi/mpi_domain.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>

#include "framework/core/errors.h"
#include "framework/particles/particles.h"
#include "framework/world/coupling.h"
#include "framework/world/periodic_domain.h"

namespace upf {

namespace {

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> at(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) at[r] = at[r - 1] + counts[r - 1];
  return at;
}

// Whether the ball of radius `margin` around x lies strictly inside the box [lo, hi].
bool inside_box(const Vec3& x, Real margin, const double lo[3], const double hi[3]) {
  for (int a = 0; a < 3; ++a)
    if (!(double(x[a] - margin) > lo[a] && double(x[a] + margin) < hi[a])) return false;
  return true;
}

// The work a particle costs a rank, relative to a liquid or granular particle, for the domain
// cuts. Wall and body particles are never queried for neighbours nor moved by a solver: they
// cost the grid's sort and their place among the candidates of the moving particles near them.
// Counted as one each, a rank holding the walls around a dam break's empty half got a fraction
// of the liquid and waited for the other at every refresh.
// 0.1 was measured on bench_mpi_scaling's dam break (2 ranks x 1 thread against 1 x 2; 1, 0.25,
// 0.1 and 0.03 tried, docs/mpi.md).
float balance_weight(ParticleType t) {
  constexpr float kBoundary = 0.1f;
  return t == ParticleType::Frozen || t == ParticleType::Rigid ? kBoundary : 1.0f;
}

int total(const std::vector<int>& counts) {
  return std::accumulate(counts.begin(), counts.end(), 0);
}

int byte_count(std::size_t bytes) {
  if (bytes > std::size_t(std::numeric_limits<int>::max()))
    throw std::runtime_error("MPI: one exchange of " + std::to_string(bytes) +
                             " bytes exceeds what one message carries; use more ranks");
  return int(bytes);
}

}  // namespace

MpiDomain::MpiDomain(MPI_Comm comm, Real reach, int rebalance_every, const PeriodicBox& periodic)
    : comm_(comm), reach_(reach), rebalance_every_(rebalance_every), periodic_(periodic) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
  rcb_ = std::make_unique<ZoltanRcb>(comm_);
  ghost_sends_.resize(std::size_t(ranks_));
  ghost_shift_sends_.resize(std::size_t(ranks_));
  ghost_receives_.assign(std::size_t(ranks_), 0);
  send_scratch_.resize(std::size_t(ranks_));
  halo_senders_.resize(std::size_t(ranks_));
  halo_receivers_.resize(std::size_t(ranks_));
}

void MpiDomain::sum(std::int64_t* values, std::size_t count) const {
  MPI_Allreduce(MPI_IN_PLACE, values, int(count), MPI_INT64_T, MPI_SUM, comm_);
}

double MpiDomain::max(double local) const {
  MPI_Allreduce(MPI_IN_PLACE, &local, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return local;
}

double MpiDomain::min(double local) const {
  MPI_Allreduce(MPI_IN_PLACE, &local, 1, MPI_DOUBLE, MPI_MIN, comm_);
  return local;
}

double MpiDomain::sum_of_doubles(double local) const {
  // Gathered and added in rank order: the same value on every rank.
  std::vector<double> all(static_cast<std::size_t>(ranks_));
  MPI_Allgather(&local, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, comm_);
  return std::accumulate(all.begin(), all.end(), 0.0);
}

const std::vector<std::uint8_t>& MpiDomain::all_to_all(
    const std::vector<std::vector<std::uint8_t>>& sends, std::vector<int>& counts) const {
  // Scratch kept between calls: a refresh runs after every stage.
  std::vector<int> send_counts(static_cast<std::size_t>(ranks_));
  flat_scratch_.clear();
  for (int r = 0; r < ranks_; ++r) {
    send_counts[std::size_t(r)] = byte_count(sends[std::size_t(r)].size());
    flat_scratch_.insert(flat_scratch_.end(), sends[std::size_t(r)].begin(),
                         sends[std::size_t(r)].end());
  }
  counts.assign(std::size_t(ranks_), 0);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  const std::vector<int> send_at = displacements(send_counts), receive_at = displacements(counts);
  received_scratch_.resize(std::size_t(total(counts)));
  MPI_Alltoallv(flat_scratch_.data(), send_counts.data(), send_at.data(), MPI_BYTE,
                received_scratch_.data(), counts.data(), receive_at.data(), MPI_BYTE, comm_);
  return received_scratch_;
}

void MpiDomain::distribute(Particles& particles, CouplingArrays& coupling) {
  particles_ = &particles;
  coupling_ = &coupling;
  const std::size_t n = particles.size();
  if (n < std::size_t(ranks_))
    throw InputError("mpirun -n " + std::to_string(ranks_),
                     std::to_string(ranks_) + " ranks for " + std::to_string(n) +
                         " particles would leave ranks with empty domains: use at most " +
                         std::to_string(n) + " ranks");
  // Every rank holds the whole scene: each keeps every ranks-th particle, then the first
  // exchange cuts the domains and moves them.
  std::vector<std::uint8_t> doomed(n, 1);
  for (std::size_t i = std::size_t(rank_); i < n; i += std::size_t(ranks_)) doomed[i] = 0;
  particles.remove(doomed);
  particles.set_ghost_count(0);
  balanced_ = false;
  migrate();
}

void MpiDomain::migrate() {
  Particles& p = *particles_;
  const std::size_t owned = p.owned_size();
  // What left the periodic box comes back through the opposite face.
  if (periodic_.any()) wrap_moving_particles(p, periodic_);
  if (!balanced_) {
    balance_weights_.resize(owned);
    for (std::size_t i = 0; i < owned; ++i) balance_weights_[i] = balance_weight(p.type[i]);
    rcb_->balance(p.position.data(), balance_weights_.data(), owned);
    balanced_ = true;
  }
  std::vector<std::vector<std::uint32_t>> leaving(static_cast<std::size_t>(ranks_));
  std::vector<std::uint8_t> doomed(owned, 0);
  double lo[3], hi[3];
  rcb_->box(rank_, lo, hi);
  for (std::size_t i = 0; i < owned; ++i) {
    // Strictly inside this rank's box: its own, without asking Zoltan (most particles).
    if (inside_box(p.position[i], 0, lo, hi)) continue;
    const int to = rcb_->owner(p.position[i]);
    if (to == rank_) continue;
    leaving[std::size_t(to)].push_back(std::uint32_t(i));
    doomed[i] = 1;
  }
  departed_.assign(leaving.size(), {});
  for (std::size_t r = 0; r < leaving.size(); ++r)
    for (std::uint32_t i : leaving[r]) departed_[r].push_back(p.id[i]);
  std::vector<int> counts;
  const std::vector<std::uint8_t>& arrived = send_particles(leaving, counts);
  p.remove(doomed);
  const std::vector<std::size_t> from = append_arrivals(arrived, counts);
  traffic_.migrated = std::accumulate(from.begin(), from.end(), std::size_t(0));
}

const std::vector<std::uint8_t>& MpiDomain::send_particles(
    const std::vector<std::vector<std::uint32_t>>& lists, std::vector<int>& counts) const {
  for (int r = 0; r < ranks_; ++r) {
    auto& out = send_scratch_[std::size_t(r)];
    out.clear();
    const auto& list = lists[std::size_t(r)];
    particles_->pack(list.data(), list.size(), out);
  }
  return all_to_all(send_scratch_, counts);
}

std::vector<std::size_t> MpiDomain::append_arrivals(const std::vector<std::uint8_t>& arrived,
                                                    const std::vector<int>& counts) {
  const std::size_t per_particle = particles_->packed_size();
  std::vector<std::size_t> particles(counts.size(), 0);
  const std::uint8_t* at = arrived.data();
  for (std::size_t r = 0; r < counts.size(); ++r) {
    particles[r] = std::size_t(counts[r]) / per_particle;
    particles_->append_packed(at, particles[r]);
    at += counts[r];
  }
  return particles;
}

void MpiDomain::exchange(std::uint64_t step) {
  if (rebalance_every_ > 0 && step % std::uint64_t(rebalance_every_) == 0) balanced_ = false;
  migrate();
  make_ghosts();
}

void MpiDomain::make_ghosts() {
  Particles& p = *particles_;
  const std::size_t owned = p.owned_size();
  double lo[3], hi[3];
  rcb_->box(rank_, lo, hi);
  // A little beyond the support radius: a neighbour at exactly the radius must not be lost to
  // the rounding of the box test.
  const Real reach = reach_ * Real(1.0001);
  std::vector<int> touching;
  for (auto& list : ghost_sends_) list.clear();
  for (auto& list : ghost_shift_sends_) list.clear();
  for (auto& sender : halo_senders_) sender.forget();
  const Vec3 r{reach, reach, reach};
  // Every rank whose domain holds a place within reach of `at` gets particle i, shifted.
  auto send_to_ranks_near = [&](std::size_t i, const Vec3& at, const Vec3& shift, bool self) {
    rcb_->ranks_touching(at - r, at + r, touching);
    for (int to : touching) {
      if (to == rank_ && !self) continue;
      ghost_sends_[std::size_t(to)].push_back(std::uint32_t(i));
      if (periodic_.any()) ghost_shift_sends_[std::size_t(to)].push_back(shift);
    }
  };
  for (std::size_t i = 0; i < owned; ++i) {
    const Vec3& x = p.position[i];
    // No other domain within reach: no ghost unless a periodic face is.
    if (!inside_box(x, reach, lo, hi)) send_to_ranks_near(i, x, Vec3{}, false);
    periodic_.for_each_image_shift(x, reach, [&](const Vec3& shift) {
      send_to_ranks_near(i, PeriodicBox::shifted(x, shift), shift, true);
    });
  }
  std::vector<int> counts;
  const std::vector<std::uint8_t>& arrived = send_particles(ghost_sends_, counts);
  ghost_receives_ = append_arrivals(arrived, counts);
  const std::size_t ghosts =
      std::accumulate(ghost_receives_.begin(), ghost_receives_.end(), std::size_t(0));
  p.set_ghost_count(ghosts);
  ghost_shifts_.clear();
  if (periodic_.any()) {
    // The shifts follow the ghosts, in the same rank order.
    for (int to = 0; to < ranks_; ++to) {
      const auto& shifts = ghost_shift_sends_[std::size_t(to)];
      auto& out = send_scratch_[std::size_t(to)];
      out.resize(shifts.size() * sizeof(Vec3));
      if (!shifts.empty()) std::memcpy(out.data(), shifts.data(), out.size());
    }
    const std::vector<std::uint8_t>& received = all_to_all(send_scratch_, counts);
    ghost_shifts_.resize(ghosts);
    if (ghosts)
      std::memcpy(static_cast<void*>(ghost_shifts_.data()), received.data(), ghosts * sizeof(Vec3));
    shift_ghosts();
  }
  traffic_.owned = owned;
  traffic_.ghosts = ghosts;
  traffic_.halo_bytes = 0;
  traffic_.halo_refreshes = 0;
}

std::vector<std::vector<Vec3>*> MpiDomain::carried_coupling() const {
  std::vector<std::vector<Vec3>*> carried;
  for (int a = 0; a < kCouplingArrayCount; ++a) {
    const auto array = CouplingArray(a);
    if (coupling_->active(array) && (*coupling_)[array].size() == particles_->size())
      carried.push_back(&(*coupling_)[array]);
  }
  return carried;
}

const std::vector<std::size_t>& MpiDomain::halo_segments(std::size_t count,
                                                         std::size_t coupling) const {
  segment_scratch_.clear();
  for (const std::size_t bytes : element_sizes_) segment_scratch_.push_back(bytes * count);
  segment_scratch_.insert(segment_scratch_.end(), coupling, count * sizeof(Vec3));
  return segment_scratch_;
}

void MpiDomain::pack_ghosts(const std::vector<std::uint32_t>& indices,
                            const std::vector<std::vector<Vec3>*>& coupling,
                            std::vector<std::uint8_t>& out) const {
  out.clear();
  particles_->pack(indices.data(), indices.size(), out);
  for (const std::vector<Vec3>* array : coupling) {
    const std::vector<Vec3>& values = *array;
    const std::size_t start = out.size();
    out.resize(start + indices.size() * sizeof(Vec3));
    for (std::size_t k = 0; k < indices.size(); ++k)
      std::memcpy(out.data() + start + k * sizeof(Vec3), &values[indices[k]], sizeof(Vec3));
  }
}

void MpiDomain::shift_ghosts() const {
  shift_ghost_positions(*particles_, ghost_shifts_);
}

void MpiDomain::refresh_ghosts() const {
  if (!particles_ || (ranks_ == 1 && !periodic_.any())) return;
  Particles& p = *particles_;
  const std::vector<std::vector<Vec3>*> coupling = carried_coupling();
  element_sizes_ = p.packed_element_sizes();  // once a refresh, not once per rank and side
  for (int r = 0; r < ranks_; ++r) {
    const std::vector<std::uint32_t>& sends = ghost_sends_[std::size_t(r)];
    send_scratch_[std::size_t(r)].clear();
    if (sends.empty()) continue;
    pack_ghosts(sends, coupling, packet_scratch_);
    halo_senders_[std::size_t(r)].encode(packet_scratch_,
                                         halo_segments(sends.size(), coupling.size()),
                                         send_scratch_[std::size_t(r)]);
    traffic_.halo_bytes += send_scratch_[std::size_t(r)].size();
  }
  std::vector<int> counts;
  const std::vector<std::uint8_t>& arrived = all_to_all(send_scratch_, counts);
  const std::uint8_t* at = arrived.data();
  std::size_t first = p.owned_size();
  for (int r = 0; r < ranks_; ++r) {
    const std::size_t count = ghost_receives_[std::size_t(r)];
    if (count) {
      const std::vector<std::uint8_t>& packet = halo_receivers_[std::size_t(r)].decode(
          at, std::size_t(counts[std::size_t(r)]), halo_segments(count, coupling.size()));
      p.overwrite_packed(first, packet.data(), count);
      const std::uint8_t* values = packet.data() + count * p.packed_size();
      for (std::vector<Vec3>* out : coupling) {
        std::memcpy(static_cast<void*>(&(*out)[first]), values, count * sizeof(Vec3));
        values += count * sizeof(Vec3);
      }
    }
    at += counts[std::size_t(r)];
    first += count;
  }
  shift_ghosts();
  ++traffic_.halo_refreshes;
}

void MpiDomain::drop_ghosts() {
  particles_->truncate(particles_->owned_size());
  particles_->set_ghost_count(0);
  for (auto& list : ghost_sends_) list.clear();
  for (auto& list : ghost_shift_sends_) list.clear();
  for (auto& sender : halo_senders_) sender.forget();
  ghost_shifts_.clear();
  std::fill(ghost_receives_.begin(), ghost_receives_.end(), 0);
}

void MpiDomain::gather(const Particles& owned, Particles& whole) const {
  std::vector<std::uint32_t> all(owned.owned_size());
  std::iota(all.begin(), all.end(), 0u);
  std::vector<std::uint8_t> mine;
  owned.pack(all.data(), all.size(), mine);
  const int my_bytes = byte_count(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks_), 0);
  MPI_Gather(&my_bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_);
  const std::vector<int> at = displacements(counts);
  std::vector<std::uint8_t> received(rank_ == 0 ? std::size_t(total(counts)) : 0);
  MPI_Gatherv(mine.data(), my_bytes, MPI_BYTE, received.data(), counts.data(), at.data(), MPI_BYTE,
              0, comm_);
  if (rank_ != 0) {
    whole = Particles();
    return;
  }
  whole = owned;
  whole.truncate(owned.owned_size());
  whole.set_ghost_count(0);
  const std::size_t per_particle = owned.packed_size();
  for (int r = 1; r < ranks_; ++r)
    whole.append_packed(received.data() + at[std::size_t(r)],
                        std::size_t(counts[std::size_t(r)]) / per_particle);
  // In id order: the frames of any rank count list the particles alike.
  whole.sort_by_id();
}

std::vector<std::uint8_t> MpiDomain::exchange_bytes(
    const std::vector<std::vector<std::uint8_t>>& sends) const {
  std::vector<int> counts;
  return all_to_all(sends, counts);
}

std::vector<std::uint8_t> MpiDomain::all_gather(const std::vector<std::uint8_t>& mine) const {
  const int my_bytes = byte_count(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks_), 0);
  MPI_Allgather(&my_bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  const std::vector<int> at = displacements(counts);
  std::vector<std::uint8_t> all(std::size_t(total(counts)));
  MPI_Allgatherv(mine.data(), my_bytes, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE,
                 comm_);
  return all;
}

void MpiDomain::broadcast(std::vector<char>& bytes) const {
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, comm_);
  bytes.resize(std::size_t(size));
  // In pieces: a checkpoint may exceed what one message's int count carries.
  constexpr std::size_t kPiece = std::size_t(1) << 30;
  for (std::size_t at = 0; at < bytes.size(); at += kPiece)
    MPI_Bcast(bytes.data() + at, int(std::min(kPiece, bytes.size() - at)), MPI_BYTE, 0, comm_);
}

}  // namespace upf
