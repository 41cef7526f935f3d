// SPlisHSPlasH's own dam break (its data/Scenes/DamBreakModel.json) run by every pressure solver
// of upf, for comparing with SPlisHSPlasH's figures (figures, never pass/fail). The scene: a tank
// [-2, 0, -0.75] - [2, 3, 1.5] m reduced to its inside [-2, 0, -0.75] - [2, 3, 0.75], the fluid
// block [-1.95, 0.05, -0.5] - [-0.95, 1.05, 0.5], 2.5 cm spacing, viscosity 1e-4 m^2/s, Akinci
// walls, 0.5 s from rest. Prints per solver: wall seconds per simulated second, fluid
// particle-steps per second, mean dt and iterations, and the density error at the particles'
// positions (the density every step computes at its start), averaged over the steps and at its
// largest.
//   bench_splishsplash_dam_break [--threads N] [--end T] [--spacing H] [--cfl C] [--solvers JSON]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "framework/core/stopwatch.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

namespace {

nlohmann::json dam_break_model(double spacing, double cfl, const nlohmann::json& solver) {
  return {
      {"name", "splishsplash_dam_break"},
      {"particle_spacing", spacing},
      {"materials",
       {{"water", {{"type", "liquid"}, {"density", 1000}, {"viscosity", 1e-4}, {"solver", solver}}},
        {"wall", {{"type", "frozen"}}}}},
      {"containers", {{{"material", "wall"}, {"min", {-2, 0, -0.75}}, {"max", {2, 3, 0.75}}}}},
      {"fluid_blocks",
       {{{"material", "water"}, {"min", {-1.95, 0.05, -0.5}}, {"max", {-0.95, 1.05, 0.5}}}}},
      {"time", {{"end", 0.5}, {"dt_max", 0.005}, {"cfl", cfl}}},
  };
}

// The relative compression at the particles' positions: the density field each step writes
// for the current positions before its pressure solve.
struct Compression {
  double sum = 0, max = 0;
  std::size_t count = 0;
};

Compression compression(const upf::World& world, double rho0) {
  const upf::Particles& p = world.particles();
  const upf::Real* density = p.find_scalar("density")->data();
  Compression c;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != upf::ParticleType::Liquid) continue;
    const double e = std::max(0.0, (double(density[i]) - rho0) / rho0);
    c.sum += e;
    c.max = std::max(c.max, e);
    ++c.count;
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  int threads = 2;
  double end = 0.5, spacing = 0.025, cfl = 0.4;
  std::string solvers = R"([{"name":"pcisph","eta":0.01},{"name":"pcisph","eta":0.0005},)"
                        R"({"name":"dfsph","eta":0.0005},{"name":"iisph","eta":0.0005}])";
  CLI::App app{"SPlisHSPlasH DamBreakModel, every pressure solver"};
  app.add_option("--threads", threads);
  app.add_option("--end", end, "simulated seconds");
  app.add_option("--spacing", spacing, "particle spacing in m");
  app.add_option("--cfl", cfl, "CFL number (the scene key time/cfl)");
  app.add_option("--solvers", solvers, "a JSON array of solver objects, as in scene files");
  CLI11_PARSE(app, argc, argv);

  try {
    upf::Registry registry;
    upf::register_builtins(registry);
    std::printf("%-36s %9s %10s %9s %6s %9s %9s\n", "solver", "wall/sim", "fpsteps/s", "mean dt",
                "iters", "avg err", "max err");
    for (const auto& solver : nlohmann::json::parse(solvers)) {
      const upf::SceneDescription scene =
          upf::read_scene(dam_break_model(spacing, cfl, solver), registry, "bench");
      auto world = upf::build_world(scene, registry, threads);
      world->prepare();
      const std::size_t liquid = world->particles().count(upf::ParticleType::Liquid);
      double wall_ms = 0, iterations = 0, error_sum = 0, error_max = 0;
      std::size_t steps = 0;
      upf::Stopwatch clock;
      while (world->time() < end - 1e-12) {
        world->step(world->next_time_step_until(end));
        wall_ms += world->last_step().total_ms;
        iterations += world->last_step().solver.iterations;
        const Compression c = compression(*world, 1000.0);
        error_sum += c.sum / double(std::max<std::size_t>(c.count, 1));
        error_max = std::max(error_max, c.max);
        ++steps;
      }
      const double s = double(steps);
      std::printf("%-36s %9.1f %10.3g %8.3gms %6.2f %8.3f%% %8.2f%%  (%zu liquid particles)\n",
                  solver.dump().c_str(), wall_ms / 1000.0 / end,
                  double(liquid) * s / (wall_ms / 1000), 1000 * end / s, iterations / s,
                  100 * error_sum / s, 100 * error_max, liquid);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {  // a bad --solvers entry or scene value
    std::fprintf(stderr, "bench_splishsplash_dam_break: %s\n", e.what());
    return 2;
  }
  return 0;
}
