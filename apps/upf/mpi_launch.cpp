#include "mpi_launch.h"

#include <cstdlib>

#include "framework/core/errors.h"

namespace upf::app {

namespace {
// A whole number >= 0 from the variable's text, or nothing.
std::optional<int> whole(const char* text) {
  if (!text || !*text) return std::nullopt;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (*end != '\0' || v < 0 || v > 1 << 24) return std::nullopt;
  return int(v);
}
}  // namespace

LaunchedRanks launched_ranks(const std::function<const char*(const char*)>& getenv) {
  static constexpr const char* kPairs[][2] = {{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
                                              {"PMI_SIZE", "PMI_RANK"},
                                              {"SLURM_STEP_NUM_TASKS", "SLURM_PROCID"}};
  for (const auto& [size_name, rank_name] : kPairs) {
    const auto size = whole(getenv(size_name));
    const auto rank = whole(getenv(rank_name));
    if (size && rank && *size >= 1) return {*size, *rank, size_name};
  }
  return {};
}

void refuse_several_ranks(const LaunchedRanks& ranks, const std::string& command) {
  if (ranks.size <= 1) return;
  const std::string where = "mpirun -n " + std::to_string(ranks.size) + " (" + ranks.variable +
                            "=" + std::to_string(ranks.size) + ")";
  const std::string each =
      std::to_string(ranks.size) + " ranks would each do the whole job into the same files. ";
  if (command == "run")
    throw InputError(where,
                     "this upf was built without MPI (the CMake option UPF_MPI, which "
                     "needs libopenmpi-dev and libtrilinos-zoltan-dev), so " +
                         each +
                         "Rebuild with them, or start it as one process (OpenMP uses the "
                         "cores: --threads N)");
  if (command == "compare")
    throw InputError(where, "upf compare runs on one rank: " + each +
                                "Spread a comparison's runs over nodes with upf compare --plan / "
                                "--task K (docs/compare.md)");
  throw InputError(where, "upf " + command + " runs on one rank: " + each +
                              "Start it as one process (--threads N)");
}

}  // namespace upf::app
