// The MPI implementation of ParticleDomain (framework/world/particle_domain.h): Zoltan's
// recursive coordinate bisection for the domains (zoltan_rcb.h), migration and ghosts by
// all-to-all exchanges of packed particles (Particles::pack), and the collectives as
// MPI_Allreduce over exact integer sums and exact extremes.
//
// Ghosts reach one support radius from each domain's faces: every neighbour list of an owned
// particle is then complete. Every array of a ghost (built-in, named fields, the active coupling
// arrays) is refreshed after every particle stage, so a solver needs no list of what it reads.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "framework/core/real.h"
#include "framework/mpi/halo_delta.h"
#include "framework/mpi/zoltan_rcb.h"
#include "framework/world/particle_domain.h"
#include "framework/world/periodic_box.h"

namespace upf {

class MpiDomain final : public ParticleDomain {
 public:
  // `reach`: how far from a domain its ghosts reach (the support radius); new cuts every
  // `rebalance_every` steps (0: only the first). Along `periodic`'s axes the world repeats:
  // the ghosts then include the periodic images (periodic_box.h), shifted by the period, sent
  // to whichever rank (this one too) holds the place they land on.
  MpiDomain(MPI_Comm comm, Real reach, int rebalance_every, const PeriodicBox& periodic = {});

  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  void sum(std::int64_t* values, std::size_t count) const override;
  double max(double local) const override;
  double min(double local) const override;
  double sum_of_doubles(double local) const override;
  void refresh_ghosts() const override;

  void distribute(Particles& particles, CouplingArrays& coupling) override;
  void exchange(std::uint64_t step) override;
  void drop_ghosts() override;
  bool owns(const Vec3& x) const override { return rcb_->owner(x) == rank_; }
  void gather(const Particles& owned, Particles& whole) const override;
  const std::vector<std::vector<std::uint32_t>>& departed() const override { return departed_; }
  std::vector<std::uint8_t> exchange_bytes(
      const std::vector<std::vector<std::uint8_t>>& sends) const override;
  std::vector<std::uint8_t> all_gather(const std::vector<std::uint8_t>& mine) const override;
  void broadcast(std::vector<char>& bytes) const override;
  DomainTraffic traffic() const override { return traffic_; }

 private:
  // Sends sends[r] to rank r; returns everything received, in rank order, with each rank's share
  // in `counts` (bytes). The bytes are valid until the next exchange.
  const std::vector<std::uint8_t>& all_to_all(const std::vector<std::vector<std::uint8_t>>& sends,
                                              std::vector<int>& counts) const;
  // Packs lists[r]'s particles for rank r and exchanges them; the bytes received, in rank order,
  // with each rank's share in `counts`.
  const std::vector<std::uint8_t>& send_particles(
      const std::vector<std::vector<std::uint32_t>>& lists, std::vector<int>& counts) const;
  // Appends what send_particles received; the particles that came from each rank.
  std::vector<std::size_t> append_arrivals(const std::vector<std::uint8_t>& arrived,
                                           const std::vector<int>& counts);
  // Owned particles whose position lies in another rank's domain move there.
  void migrate();
  void make_ghosts();
  // Ghost k's position += ghost_shifts_[k] (the periodic images; zero for the others).
  void shift_ghosts() const;
  // The coupling arrays ghosts carry: the active ones, sized for this step.
  std::vector<std::vector<Vec3>*> carried_coupling() const;
  // The byte lengths of a packet of `count` ghosts' arrays (element_sizes_), then of `coupling`
  // arrays of them.
  const std::vector<std::size_t>& halo_segments(std::size_t count, std::size_t coupling) const;
  // Packs the listed particles' arrays and their values in `coupling`.
  void pack_ghosts(const std::vector<std::uint32_t>& indices,
                   const std::vector<std::vector<Vec3>*>& coupling,
                   std::vector<std::uint8_t>& out) const;

  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
  Real reach_;
  int rebalance_every_;
  bool balanced_ = false;
  std::unique_ptr<ZoltanRcb> rcb_;
  std::vector<float> balance_weights_;  // per owned particle, for rcb_->balance
  Particles* particles_ = nullptr;
  CouplingArrays* coupling_ = nullptr;
  PeriodicBox periodic_;
  std::vector<std::vector<std::uint32_t>> ghost_sends_;  // per rank: owned indices it ghosts
  std::vector<std::vector<Vec3>> ghost_shift_sends_;     // per rank: their shifts (periodic)
  std::vector<Vec3> ghost_shifts_;                       // per ghost held: its shift (periodic)
  std::vector<std::size_t> ghost_receives_;              // per rank: ghosts it sent here
  std::vector<std::vector<std::uint32_t>> departed_;     // per rank: ids migrated there
  mutable std::vector<std::vector<std::uint8_t>> send_scratch_;
  // Ghost refreshes send only the arrays that changed (halo_delta.h): per rank, both sides.
  mutable std::vector<HaloDeltaSender> halo_senders_;
  mutable std::vector<HaloDeltaReceiver> halo_receivers_;
  mutable std::vector<std::uint8_t> packet_scratch_;
  mutable std::vector<std::size_t> segment_scratch_;
  mutable std::vector<std::size_t> element_sizes_;  // Particles::packed_element_sizes, this refresh
  mutable std::vector<std::uint8_t> flat_scratch_, received_scratch_;  // all_to_all's buffers
  mutable DomainTraffic traffic_;
};

}  // namespace upf
