// Whether an MPI launcher (mpirun, mpiexec, srun) started this process as one of several ranks,
// read from the environment the launchers set. `upf run` splits its scene over the ranks when
// built with MPI (UPF_MPI, mpi_run.h); every other command, and `upf run` built without MPI,
// would have each rank do the whole job into the same files, so it refuses before it writes
// anything. One rank runs as it would alone.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace upf::app {

struct LaunchedRanks {
  int size = 1;          // ranks the launcher started
  int rank = 0;          // this process's
  std::string variable;  // the environment variable that told: "OMPI_COMM_WORLD_SIZE"
};

// From `getenv` (std::getenv by default): Open MPI's OMPI_COMM_WORLD_SIZE/RANK, MPICH's and
// Intel MPI's PMI_SIZE/PMI_RANK, Slurm's SLURM_STEP_NUM_TASKS/SLURM_PROCID (srun). Unset: one.
LaunchedRanks launched_ranks(const std::function<const char*(const char*)>& getenv =
                                 [](const char* name) {
                                   return static_cast<const char*>(std::getenv(name));
                                 });

// Throws InputError when `ranks` holds more than one and `command` ("run", "compare", "render")
// does not run split over ranks here: what upf can do instead. On ranks other than 0 the caller
// should stay quiet (rank 0 says it).
void refuse_several_ranks(const LaunchedRanks& ranks, const std::string& command);

}  // namespace upf::app
