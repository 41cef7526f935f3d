// Split-world scaling (figures, never pass/fail; issue 23): the PCISPH dam break split over the
// ranks mpirun started. Prints, from rank 0, the wall time per step (slowest rank), fluid
// particle-steps per second, the ghosts as a share of the owned particles, and the halo bytes per
// step and per ghost refresh (summed over ranks), which bench/README.md's communication model
// extrapolates from.
//   mpirun -n P bench_mpi_scaling [--threads N] [--spacing H] [--steps S] [--weak]
// --weak scales the block with the rank count (the same particles per rank).
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "framework/core/stopwatch.h"
#include "framework/mpi/mpi_domain.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int threads = 1, steps = 50, rebalance_every = 10;
  double spacing = 0.02;
  bool weak = false;
  CLI::App app{"split-world scaling of the PCISPH dam break"};
  app.add_option("--threads", threads, "OpenMP threads per rank");
  app.add_option("--steps", steps, "measured steps (after 10 warm-up steps)");
  app.add_option("--spacing", spacing, "particle spacing in m at one rank");
  app.add_option("--rebalance-every", rebalance_every);
  app.add_flag("--weak", weak, "the same particles per rank: the spacing shrinks as ranks^(1/3)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    MPI_Finalize();
    return code;
  }

  upf::Registry registry;
  upf::register_builtins(registry);
  std::ifstream in(std::filesystem::path(UPF_SOURCE_DIR) / "samples" / "dam_break.json");
  auto doc = nlohmann::json::parse(in);
  doc["particle_spacing"] = weak ? spacing / std::cbrt(double(ranks)) : spacing;
  const upf::SceneDescription scene = upf::read_scene(doc, registry, "bench");
  auto world = upf::build_world(scene, registry, threads);
  world->prepare();
  const std::size_t liquid = world->particles().count(upf::ParticleType::Liquid);
  const std::size_t total = world->particles().size();
  world->set_domain(std::make_unique<upf::MpiDomain>(
      MPI_COMM_WORLD, world->settings().support_radius(), rebalance_every));
  for (int s = 0; s < 10; ++s) world->step(world->next_time_step());

  double ghosts = 0, owned = 0, halo_bytes = 0, refreshes = 0, iterations = 0;
  MPI_Barrier(MPI_COMM_WORLD);
  const upf::Stopwatch wall;
  for (int s = 0; s < steps; ++s) {
    world->step(world->next_time_step());
    const upf::DomainTraffic t = world->domain()->traffic();
    ghosts += double(t.ghosts);
    owned += double(t.owned);
    halo_bytes += double(t.halo_bytes);
    refreshes += double(t.halo_refreshes);
    iterations += world->last_step().solver.iterations;
  }
  double ms = wall.elapsed_ms();
  MPI_Allreduce(MPI_IN_PLACE, &ms, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  for (double* v : {&ghosts, &owned, &halo_bytes})
    MPI_Allreduce(MPI_IN_PLACE, v, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf(
        "ranks %d  threads/rank %d  particles %zu (liquid %zu)  ms/step %.2f  "
        "fluid particle-steps/s %.3g  ghosts/owned %.3f  halo MB/step %.3f  "
        "halo kB/refresh %.1f  refreshes/step %.1f  PCISPH iterations/step %.2f\n",
        ranks, threads, total, liquid, ms / steps, double(liquid) * steps / (ms / 1000.0),
        ghosts / owned, halo_bytes / steps / 1e6, halo_bytes / std::max(1.0, refreshes) / 1e3,
        refreshes / steps, iterations / steps);
  }
  world.reset();
  MPI_Finalize();
  return 0;
}
