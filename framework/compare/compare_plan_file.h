// A comparison split over processes (a Slurm job array, GNU parallel, a shell loop): `upf compare
// --plan` writes OUT/plan.json; each `upf compare --task K` runs the plan's run K into
// OUT/<solver>/ (summary.json included); `upf compare --collect` reads the plan and the runs'
// summaries and writes the same report as a comparison run in one process.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/compare/comparison.h"

namespace upf {

inline constexpr const char* kComparePlanFile = "plan.json";

// One run of a plan: its name (row label and directory), its solver, and the sweep's --set
// arguments applied to the plan's scene before the solver is set.
struct PlannedRun {
  std::string name, solver;
  std::vector<std::string> sets;
};

struct ComparePlanFile {
  std::filesystem::path scene_file;  // absolute: relative paths in the scene resolve against it
  nlohmann::json scene;              // the scene document with the --set overrides applied
  std::vector<PlannedRun> runs;      // task K runs runs[K]; the report's row order
  std::optional<double> end_time;
  int threads = 0;  // 0: OpenMP's default; a task may override it
  bool write_frames = true;
  std::string date;  // UTC, ISO 8601: when the comparison was planned
};

// Writes OUT/plan.json atomically (OutputError when it cannot).
void write_compare_plan(const std::filesystem::path& out_dir, const ComparePlanFile& plan);
// Reads OUT/plan.json; InputError naming the file, and the key, when it is missing or malformed.
ComparePlanFile read_compare_plan(const std::filesystem::path& out_dir);

// The row of `run` from OUT/<run.name>/summary.json, with the probes in `probes`' order;
// InputError naming the file when the run has not finished (no summary, or an interrupted one)
// or the file is not a summary.
CompareRow read_compare_row(const std::filesystem::path& out_dir, const PlannedRun& run,
                            const std::vector<std::string>& probes);

}  // namespace upf
