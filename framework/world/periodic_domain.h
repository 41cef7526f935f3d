// A periodic domain on one process (periodic_box.h): the ParticleDomain that holds a particle's
// periodic images as ghosts, as an MPI rank holds its neighbours' particles (particle_domain.h).
//
// Each step it wraps the owned particles into the box, appends an image (the particle with its
// id, shifted by the period) of every particle within a support radius of a periodic face, and
// refreshes the images after every particle stage. Solvers, neighbour lists and kernels then
// run unchanged: a particle by a face finds its neighbours' images across it at the right
// distance, and every solver that runs across MPI ranks runs on a periodic domain.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/world/particle_domain.h"
#include "framework/world/periodic_box.h"

namespace upf {

// What MpiDomain and PeriodicDomain share. The owned particles that move (not frozen ones: a wall
// may rest exactly on a face) are wrapped into the box.
void wrap_moving_particles(Particles& particles, const PeriodicBox& box);
// Ghost k (particle owned_size() + k) gets shifts[k] added to its position and to every field of
// positions (Particles::for_each_position_array).
void shift_ghost_positions(Particles& particles, const std::vector<Vec3>& shifts);

class PeriodicDomain final : public ParticleDomain {
 public:
  // Images reach periodic_image_reach(support_radius) past a face.
  PeriodicDomain(const PeriodicBox& box, Real support_radius);

  int rank() const override { return 0; }
  int ranks() const override { return 1; }
  void sum(std::int64_t*, std::size_t) const override {}
  double max(double local) const override { return local; }
  double min(double local) const override { return local; }
  double sum_of_doubles(double local) const override { return local; }
  void refresh_ghosts() const override;

  void distribute(Particles& particles, CouplingArrays& coupling) override;
  void exchange(std::uint64_t step) override;
  void drop_ghosts() override;
  bool owns(const Vec3&) const override { return true; }
  void gather(const Particles& owned, Particles& whole) const override;
  const std::vector<std::vector<std::uint32_t>>& departed() const override { return departed_; }
  std::vector<std::uint8_t> exchange_bytes(
      const std::vector<std::vector<std::uint8_t>>& sends) const override {
    return sends.at(0);
  }
  std::vector<std::uint8_t> all_gather(const std::vector<std::uint8_t>& mine) const override {
    return mine;
  }
  void broadcast(std::vector<char>&) const override {}
  DomainTraffic traffic() const override { return traffic_; }

 private:
  // Ghost k is the image of owned particle sources_[k], shifted by shifts_[k].
  void shift_images() const;

  PeriodicBox box_;
  Real reach_;
  Particles* particles_ = nullptr;
  CouplingArrays* coupling_ = nullptr;
  std::vector<std::uint32_t> sources_;
  std::vector<Vec3> shifts_;
  std::vector<std::vector<std::uint32_t>> departed_{1};
  mutable std::vector<std::uint8_t> scratch_;
  mutable DomainTraffic traffic_;
};

}  // namespace upf
