// The figures a run adds up step by step for its summary (summary.json), kept across
// checkpoints so a resumed run reports the whole run.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "framework/run/simulation_run.h"

namespace upf {

class RunTotals {
 public:
  // Adds the world's last step, which ended with `liquid` liquid particles; the largest
  // iterations and density error go into `result`.
  void add_step(const StepReport& r, RunResult& result, std::size_t liquid);
  // Means, throughput and the rest of `result` from what was added; `result.steps` must be set.
  void finish(RunResult& result) const;
  // summary.json: `result`, the scene and its materials, median step and stage times.
  void write_summary(const std::filesystem::path& path, const SceneDescription& scene,
                     const RunResult& result) const;

  double wall_seconds_before() const { return wall_seconds_before_; }
  void save_state(StateWriter& out, const RunResult& r, double wall_seconds) const;
  void restore_state(StateReader& in, RunResult& r);

 private:
  void add_stage(const std::string& name, double ms);

  std::vector<double> step_ms_;
  std::vector<std::pair<std::string, std::vector<double>>> stages_;
  double sum_dt_ = 0, sum_iterations_ = 0, sum_avg_error_ = 0;
  // Liquid particles summed over the steps: the throughput when emitters and sinks change them.
  double sum_liquid_ = 0;
  double wall_seconds_before_ = 0;  // spent by the runs this one resumes
};

}  // namespace upf
