// metrics.csv (one row per step) and probes.csv (one row per frame): append-only logs flushed at
// every frame, so a crash or an instability loses at most the rows since the last frame.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "framework/world/world.h"

namespace upf {

struct StepMetrics {
  std::uint64_t step = 0;
  double time = 0;
  double kinetic_energy = 0;
  std::size_t count_by_type[kParticleTypeCount] = {};
};

class MetricsLog {
 public:
  explicit MetricsLog(const std::filesystem::path& path);
  void add(const StepMetrics& m, const StepReport& r);
  void flush();

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::vector<std::string> stages_;  // stage columns, fixed by the first step
};

class ProbeLog {
 public:
  ProbeLog(const std::filesystem::path& path, const std::vector<std::string>& names);
  void add(double time, const std::vector<double>& values);

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

double kinetic_energy(const Particles& particles, const CpuExecutor& exec);

}  // namespace upf
