// Dam-break benchmark (figures, never pass/fail): PCISPH at eta = 1 % on a dam break of about
// 100k liquid particles. Prints fluid particle-steps per second, milliseconds per step by stage
// (neighbour search, non-pressure forces, pressure loop, integration), mean pressure iterations
// and peak memory per particle (getrusage max RSS / particles): after the first run, one world's,
// and at the end, which also counts what the later fresh worlds added to the peak (the heap
// does not hand everything back between runs).
//   bench_dam_break [--threads N] [--steps S] [--spacing H] [--runs R] [--reorder-every K]
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "bench/bench_support.h"
#include "framework/core/stopwatch.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

using upf::bench::median;

int main(int argc, char** argv) {
  int threads = 2, steps = 100, runs = 3, reorder_every = -1;
  double spacing = 0.0125;
  CLI::App app{"PCISPH dam-break benchmark"};
  app.add_option("--threads", threads);
  app.add_option("--steps", steps, "measured steps per run (after 20 warm-up steps)");
  app.add_option("--spacing", spacing, "particle spacing in m (0.0125: 98,304 liquid particles)");
  app.add_option("--runs", runs);
  app.add_option("--reorder-every", reorder_every,
                 "steps between locality reorders (scene default)");
  CLI11_PARSE(app, argc, argv);

  upf::Registry registry;
  upf::register_builtins(registry);
  std::ifstream in(std::filesystem::path(UPF_SOURCE_DIR) / "samples" / "dam_break.json");
  auto doc = nlohmann::json::parse(in);
  doc["particle_spacing"] = spacing;
  if (reorder_every >= 0) doc["neighbours"] = {{"reorder_every", reorder_every}};
  const upf::SceneDescription scene = upf::read_scene(doc, registry, "bench");

  std::vector<double> rates, iterations;
  std::map<std::string, std::vector<double>> stage_ms;
  std::size_t liquid = 0, total = 0;
  long one_world_kib = 0;
  for (int r = 0; r < runs; ++r) {
    auto world = upf::build_world(scene, registry, threads);
    world->prepare();
    liquid = world->particles().count(upf::ParticleType::Liquid);
    total = world->particles().size();
    for (int s = 0; s < 20; ++s) world->step(world->next_time_step());
    const upf::bench::StepTimes times = upf::bench::time_steps(*world, steps);
    rates.push_back(double(liquid) * steps / (times.wall_ms / 1000.0));
    iterations.push_back(times.iterations / steps);
    for (const auto& [name, ms] : times.stage_ms) stage_ms[name].push_back(ms / steps);
    std::printf("run %d: %.3g fluid particle-steps/s\n", r + 1, rates.back());
    if (r == 0) {
      rusage first{};
      getrusage(RUSAGE_SELF, &first);
      one_world_kib = first.ru_maxrss;
    }
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("\nPCISPH dam break, eta = 1 %%, %d threads, %zu liquid + %zu boundary particles\n",
              threads, liquid, total - liquid);
  std::printf("median of %d runs of %d steps (after 20 warm-up steps, from t = 0):\n", runs, steps);
  std::printf("  fluid particle-steps per second: %.3g\n", median(rates));
  std::printf("  mean pressure iterations:        %.2f\n", median(iterations));
  for (const auto& [name, v] : stage_ms)
    std::printf("  %-12s %8.2f ms/step\n", name.c_str(), median(v));
  std::printf("  peak memory, one world: %.0f MiB, %.0f bytes per particle (all particles)\n",
              double(one_world_kib) / 1024.0, double(one_world_kib) * 1024.0 / double(total));
  std::printf("  peak memory, all %d runs: %.0f MiB, %.0f bytes per particle\n", runs,
              double(usage.ru_maxrss) / 1024.0, double(usage.ru_maxrss) * 1024.0 / double(total));
  return 0;
}
