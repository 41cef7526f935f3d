// Runs one scene once per solver, each into OUT/<solver>/ with everything `upf run` writes. A
// solver that goes unstable gets its row (status, the time it failed, the figures up to then)
// and the others still run.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "framework/compare/compare_plan.h"
#include "framework/run/simulation_run.h"

namespace upf {

struct CompareRow {
  std::string solver;
  RunResult result;  // unstable: status "unstable", failure, simulated_time = when it failed
  std::string name = solver;  // the run's name: its label and directory (SolverRunPlan::name)
  bool unstable() const { return result.status == "unstable"; }
};

struct Comparison {
  std::string scene;
  std::string source;
  std::size_t liquid_particles = 0;
  std::size_t total_particles = 0;
  int threads = 0;
  double end_time = 0;
  std::string date;  // UTC, ISO 8601: when the comparison started
  std::vector<std::string> probes;
  std::vector<std::string> probe_units;  // one per probe: "m", "Pa"
  std::vector<CompareRow> rows;

  // "name [unit]", the label of probe `i` in tables and on plot axes.
  std::string probe_label(std::size_t i) const {
    return i < probe_units.size() ? probes[i] + " [" + probe_units[i] + "]" : probes[i];
  }

  bool any_unstable() const {
    for (const auto& r : rows)
      if (r.unstable()) return true;
    return false;
  }
};

struct CompareOptions {
  std::filesystem::path out_dir = "out/compare";
  VdbFrameWriters vdb_writers;    // for the "surface" and "vdb_points" formats (see RunOptions)
  int threads = 0;                // the same for every run; 0: OpenMP's default
  bool follow_free_cores = true;  // RunOptions::follow_free_cores
  std::optional<double> end_time;
  bool write_frames = true;
  std::function<void(const SolverRunPlan&, std::size_t index, std::size_t count)> on_run_start;
  std::function<void(const RunProgress&)> on_progress;
  std::function<void(const CompareRow&)> on_run_end;
};

// `plan` must not be empty (plan_comparison guarantees it).
Comparison run_comparison(const std::vector<SolverRunPlan>& plan, const Registry& registry,
                          const CompareOptions& options);

// The pieces of run_comparison, for a comparison split over processes (compare_plan_file.h):
// the facts without rows (the date now), one run into OUT/<solver>/, and a row added.
Comparison start_comparison(const std::vector<SolverRunPlan>& plan, const CompareOptions& options);
CompareRow run_compare_entry(const SolverRunPlan& entry, const Registry& registry,
                             const CompareOptions& options);
void add_compare_row(Comparison& comparison, CompareRow row);

// Now, in UTC, ISO 8601: a comparison's date.
std::string utc_now_iso8601();

}  // namespace upf
