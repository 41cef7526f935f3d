// `mpirun -n P upf run SCENE`: the MPI session of a run split over ranks (framework/mpi/). Built
// only with UPF_MPI; without it such a launch is refused (mpi_launch.h).
#pragma once

#include <functional>
#include <memory>

#include "framework/world/particle_domain.h"

namespace upf {
class World;
}

namespace upf::app {

// MPI_Init on construction, MPI_Finalize on destruction.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank with `code`: for an error that not every rank may have met, where the
  // others would wait for it in their next exchange.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0, size_ = 1;
};

// The domain maker of RunOptions::make_domain: the world over MPI_COMM_WORLD, ghosts one support
// radius deep, new cuts every `rebalance_every` steps.
std::function<std::unique_ptr<ParticleDomain>(const World&)> mpi_domain_maker(int rebalance_every);

}  // namespace upf::app
