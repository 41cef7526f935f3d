// Device pipeline benchmark (figures, never pass/fail): the PCISPH dam break (eta = 1 %) at a
// chosen liquid particle count, or a scene file as it is, on a chosen device (cpu, omp, cuda;
// docs/device.md). Prints particle-steps per second (liquid and grains: the particles the solvers
// move), ms per step by stage, mean solver iterations, device bytes per particle against the
// pre-run estimate, and for the dam break the modelled memory traffic of a step as a fraction of a
// given copy bandwidth; appends the same as CSV rows with --csv.
//   bench_device [--device omp] [--particles 100000 | --scene FILE] [--steps 50] [--runs 3]
//                [--threads N] [--copy-gbps B] [--csv FILE]
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "coupling/bodies/bodies_section.h"
#include "device/device_pipelines.h"
#include "framework/core/errors.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

using upf::bench::median;

int main(int argc, char** argv) {
  std::string device = "omp", csv, scene_file;
  double particles = 1e5, copy_gbps = 0;
  int steps = 50, runs = 3, threads = 0;
  CLI::App app{"PCISPH dam break on a device pipeline"};
  app.add_option("--device", device, "cpu, omp or cuda");
  app.add_option("--particles", particles, "liquid particles (about) of the dam break");
  app.add_option("--scene", scene_file, "a scene file to time as it is, instead of the dam break")
      ->check(CLI::ExistingFile);
  app.add_option("--steps", steps, "measured steps per run (after 5 warm-up steps)");
  app.add_option("--runs", runs);
  app.add_option("--threads", threads, "CPU threads (0: all)");
  bool measure_copy = false;
  app.add_option("--copy-gbps", copy_gbps,
                 "device-to-device copy bandwidth (read + written) in GB/s, for the traffic "
                 "fraction");
  app.add_flag("--measure-copy", measure_copy,
               "measure the copy bandwidth first (1 GiB on cuda, 256 MiB otherwise)");
  app.add_option("--csv", csv, "append the figures to this CSV file");
  CLI11_PARSE(app, argc, argv);

  if (measure_copy) {
    copy_gbps = upf::copy_bandwidth_gbps(device, device == "cuda" ? (1u << 30) : (1u << 28));
    std::printf("copy bandwidth on %s: %.1f GB/s (read + written)\n", device.c_str(), copy_gbps);
  }
  upf::Registry registry;
  upf::register_builtins(registry);
  upf::register_coupling(registry);
  const bool dam_break = scene_file.empty();
  const std::filesystem::path path =
      dam_break ? std::filesystem::path(UPF_SOURCE_DIR) / "samples" / "dam_break.json"
                : std::filesystem::path(scene_file);
  try {
    upf::SceneDescription scene;
    if (dam_break) {
      std::ifstream in(path);
      auto doc = nlohmann::json::parse(in);
      // The water column is 0.6 x 0.8 x 0.4 m.
      doc["particle_spacing"] = std::cbrt(0.6 * 0.8 * 0.4 / particles);
      doc["materials"]["water"]["solver"] = {{"name", "pcisph"}, {"eta", 0.01}};
      scene = upf::read_scene(doc, registry, "bench");
    } else {
      scene = upf::load_scene_file(path, registry);
    }
    std::vector<double> rates, iterations, bytes;
    std::map<std::string, std::vector<double>> stage_ms;
    std::size_t liquid = 0, grains = 0, total = 0;
    double estimate = 0;
    for (int r = 0; r < runs; ++r) {
      auto world = upf::build_world(scene, registry, threads);
      world->prepare();
      // The particles the solvers move.
      liquid = world->particles().count(upf::ParticleType::Liquid);
      grains = world->particles().count(upf::ParticleType::Granular);
      total = world->particles().size();
      estimate = double(upf::estimated_device_bytes(*world));
      world->set_device(upf::make_device_pipeline(device, *world));
      for (int s = 0; s < 5; ++s) world->step(world->next_time_step());
      const upf::bench::StepTimes times = upf::bench::time_steps(*world, steps);
      rates.push_back(double(liquid + grains) * steps / (times.wall_ms / 1000.0));
      iterations.push_back(times.iterations / steps);
      for (const auto& [name, ms] : times.stage_ms) stage_ms[name].push_back(ms / steps);
      bytes.push_back(world->device() ? double(world->device()->device_bytes()) : 0.0);
      std::printf("run %d: %.3g particle-steps/s\n", r + 1, rates.back());
    }
    const double step_ms = double(liquid + grains) / median(rates) * 1000.0;
    if (dam_break)
      std::printf("\nPCISPH dam break on --device %s, eta = 1 %%, %zu liquid + %zu boundary\n",
                  device.c_str(), liquid, total - liquid);
    else
      std::printf("\n%s on --device %s: %zu liquid, %zu grains, %zu in all\n",
                  path.filename().string().c_str(), device.c_str(), liquid, grains, total);
    std::printf("median of %d runs of %d steps (after 5 warm-up steps, from t = 0):\n", runs,
                steps);
    std::printf("  particle-steps per second (liquid and grains): %.3g\n", median(rates));
    std::printf("  mean solver iterations:                        %.2f\n", median(iterations));
    for (const auto& [name, v] : stage_ms)
      std::printf("  %-12s %8.3f ms/step\n", name.c_str(), median(v));
    if (median(bytes) > 0)
      std::printf("  device memory: %.0f bytes per particle (estimate before the run: %.0f)\n",
                  median(bytes) / double(total), estimate / double(total));
    if (copy_gbps > 0 && dam_break) {
      // Recomputed gradients (FluidGradients): about 845 + 36 n bytes per liquid particle and
      // step, n fluid neighbours (taken as 40 at h = 2 s); the arithmetic.
      const double moved = double(liquid) * (845.0 + 36.0 * 40.0);
      std::printf("  modelled traffic: %.2f GB/step, %.1f %% of the %.0f GB/s copy bandwidth\n",
                  moved / 1e9, 100.0 * moved / (step_ms / 1000.0) / (copy_gbps * 1e9), copy_gbps);
    }
    if (!csv.empty()) {
      const bool fresh = !std::filesystem::exists(csv);
      std::ofstream out(csv, std::ios::app);
      if (fresh)
        out << "device,liquid,grains,total,particle_steps_per_s,iterations,bytes_per_particle,"
               "copy_gbps,stage,ms_per_step\n";
      for (const auto& [name, v] : stage_ms)
        out << device << ',' << liquid << ',' << grains << ',' << total << ',' << median(rates)
            << ',' << median(iterations) << ',' << median(bytes) / double(total) << ',' << copy_gbps
            << ',' << name << ',' << median(v) << '\n';
    }
  } catch (const upf::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
