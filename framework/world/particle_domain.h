// A world split over MPI ranks (DESIGN.md, "Beyond one machine"): which particles this rank owns,
// the ghosts it holds of its neighbours' particles, and the collectives between ranks.
//
// Every rank builds and prepares the whole scene, then World::set_domain keeps its share. Each
// step the domain moves particles whose positions left this rank's domain to their new owners
// (rebalancing every few steps), appends ghosts (copies of other ranks' particles within reach
// of this domain) at the end of the arrays, refreshes them after every particle stage
// (rank_collectives.h) and drops them at the end of the step. Neighbour lists are ordered by
// (cell, id) on a global grid origin, every reduction that steers control flow or feeds a body is
// exact, so an owned particle sees exactly what it sees on one rank: the results are the same bits
// for any rank count. The framework sees only this interface; framework/mpi/ implements it.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/vec3.h"
#include "framework/executors/rank_collectives.h"

namespace upf {

class Particles;
class CouplingArrays;

// What the domain did in the last exchange, for the metrics and the scaling benchmark.
struct DomainTraffic {
  std::uint64_t owned = 0;           // particles this rank owns
  std::uint64_t ghosts = 0;          // ghosts it holds
  std::uint64_t migrated = 0;        // particles it received from other ranks
  std::uint64_t halo_bytes = 0;      // bytes it sent in ghost refreshes since the last exchange
  std::uint64_t halo_refreshes = 0;  // ghost refreshes since the last exchange
};

class ParticleDomain : public RankCollectives {
 public:
  // After World::prepare with the whole scene on every rank: keeps this rank's share.
  virtual void distribute(Particles& particles, CouplingArrays& coupling) = 0;
  // Start of a step, before the neighbour grid: rebalances when due, moves owned particles to the
  // ranks whose domains now hold them, then appends the ghosts (Particles::set_ghost_count).
  virtual void exchange(std::uint64_t step) = 0;
  // End of a step: the ghosts go.
  virtual void drop_ghosts() = 0;
  // Whether x lies in this rank's domain (an emitted particle stays on the rank that owns it).
  virtual bool owns(const Vec3& x) const = 0;
  // Rank 0 receives every rank's owned particles sorted by id; the other ranks get none.
  virtual void gather(const Particles& owned, Particles& whole) const = 0;
  // The stable ids of the particles the last exchange moved from this rank, by destination rank:
  // a solver that keeps state by particle id outside the particle fields (DEM's springs) sends
  // it after them (Solver::split_over).
  virtual const std::vector<std::vector<std::uint32_t>>& departed() const = 0;
  // Sends sends[r] to rank r; every rank calls it. What this rank received, in rank order.
  virtual std::vector<std::uint8_t> exchange_bytes(
      const std::vector<std::vector<std::uint8_t>>& sends) const = 0;
  // Every rank's bytes, concatenated in rank order, on every rank.
  virtual std::vector<std::uint8_t> all_gather(const std::vector<std::uint8_t>& mine) const = 0;
  // Rank 0's bytes on every rank (a checkpoint: StateWriter::bytes).
  virtual void broadcast(std::vector<char>& bytes) const = 0;
  virtual DomainTraffic traffic() const = 0;
};

}  // namespace upf
