// Granular column-collapse benchmark (figures, never pass/fail): DEM (linear spring-dashpot) on
// the granular_column sample refined to about 100k grains. Prints grain-steps per second (grains
// x DEM sub-steps / wall seconds), milliseconds per world step by stage and sub-steps per step.
//   bench_column_collapse [--threads N] [--steps S] [--spacing H] [--runs R]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "bench/bench_support.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

using upf::bench::median;

int main(int argc, char** argv) {
  int threads = 2, steps = 20, runs = 3;
  double spacing = 0.0054;
  CLI::App app{"DEM granular column-collapse benchmark"};
  app.add_option("--threads", threads);
  app.add_option("--steps", steps, "measured world steps per run (after 5 warm-up steps)");
  app.add_option("--spacing", spacing, "grain diameter in m (0.0054: 101,306 grains)");
  app.add_option("--runs", runs);
  CLI11_PARSE(app, argc, argv);

  upf::Registry registry;
  upf::register_builtins(registry);
  std::ifstream in(std::filesystem::path(UPF_SOURCE_DIR) / "samples" / "granular_column.json");
  auto doc = nlohmann::json::parse(in);
  doc["particle_spacing"] = spacing;
  const upf::SceneDescription scene = upf::read_scene(doc, registry, "bench");

  std::vector<double> rates, substeps;
  std::map<std::string, std::vector<double>> stage_ms;
  std::size_t grains = 0, total = 0;
  for (int r = 0; r < runs; ++r) {
    auto world = upf::build_world(scene, registry, threads);
    world->prepare();
    grains = world->particles().count(upf::ParticleType::Granular);
    total = world->particles().size();
    for (int s = 0; s < 5; ++s) world->step(world->next_time_step());
    double wall_ms = 0, grain_steps = 0, sub = 0;
    std::map<std::string, double> stages;
    for (int s = 0; s < steps; ++s) {
      world->step(world->next_time_step());
      const auto& rep = world->last_step();
      wall_ms += rep.total_ms;
      sub += rep.solver.iterations;
      grain_steps += double(grains) * rep.solver.iterations;
      stages["neighbours"] += rep.neighbour_ms;
      for (const auto& [name, ms] : rep.stage_ms) stages[name] += ms;
    }
    rates.push_back(grain_steps / (wall_ms / 1000.0));
    substeps.push_back(sub / steps);
    for (const auto& [name, ms] : stages) stage_ms[name].push_back(ms / steps);
    std::printf("run %d: %.3g grain-steps/s\n", r + 1, rates.back());
  }
  std::printf("\nDEM column collapse, %d threads, %zu grains + %zu wall particles\n", threads,
              grains, total - grains);
  std::printf("median of %d runs of %d world steps (after 5 warm-up steps, from t = 0):\n", runs,
              steps);
  std::printf("  grain-steps per second: %.3g\n", median(rates));
  std::printf("  DEM sub-steps per world step: %.1f\n", median(substeps));
  std::printf("  ms per world step by stage:\n");
  for (const auto& [name, v] : stage_ms) std::printf("    %-16s %8.2f\n", name.c_str(), median(v));
  return 0;
}
