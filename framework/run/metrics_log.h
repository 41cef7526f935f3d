// metrics.csv (one row per step) and probes.csv (one row per frame): append-only logs flushed at
// every frame, so a crash or an instability loses at most the rows since the last frame.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/state_stream.h"
#include "framework/output/resumed_log.h"
#include "framework/world/world.h"

namespace upf {

struct StepMetrics {
  std::uint64_t step = 0;
  double time = 0;
  double kinetic_energy = 0;
  std::size_t count_by_type[kParticleTypeCount] = {};
};

// Both logs start a new file, or (restore_state, for a resumed run) go on from the length the
// file had at the checkpoint: rows written after it are dropped and written again.
class MetricsLog {
 public:
  // `stages`: the world's stage list (World::stage_names()), one timing column each.
  // `resuming`: the file is left alone until restore_state opens it. `sources`: the world has
  // emitters or sinks, and each row says the mass they added and removed before its step.
  // `viscosity_solve`: a liquid's viscosity is implicit, and each row says how many conjugate
  // gradient iterations its solve took.
  MetricsLog(const std::filesystem::path& path, std::vector<std::string> stages,
             bool resuming = false, bool sources = false, bool viscosity_solve = false);
  void add(const StepMetrics& m, const StepReport& r);
  void flush();
  void save_state(StateWriter& out);
  void restore_state(StateReader& in);

 private:
  ResumableLog log_;
  std::vector<std::string> stages_;  // stage columns
  bool sources_ = false;
  bool viscosity_solve_ = false;
};

class ProbeLog {
 public:
  ProbeLog(const std::filesystem::path& path, const std::vector<std::string>& names,
           bool resuming = false);
  void add(double time, const std::vector<double>& values);
  void save_state(StateWriter& out);
  void restore_state(StateReader& in);

 private:
  ResumableLog log_;
};

double kinetic_energy(const Particles& particles, const CpuExecutor& exec);

}  // namespace upf
