#include "mpi_run.h"

#include <mpi.h>

#include "framework/mpi/mpi_domain.h"
#include "framework/world/world.h"

namespace upf::app {

MpiSession::MpiSession(int* argc, char*** argv) {
  MPI_Init(argc, argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

void MpiSession::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);  // MPI_Abort does not return; this keeps [[noreturn]] honest
}

std::function<std::unique_ptr<ParticleDomain>(const World&)> mpi_domain_maker(int rebalance_every) {
  return [rebalance_every](const World& world) -> std::unique_ptr<ParticleDomain> {
    return std::make_unique<MpiDomain>(MPI_COMM_WORLD, world.settings().support_radius(),
                                       rebalance_every, world.settings().periodic);
  };
}

}  // namespace upf::app
