// The solvers' tables (Solver::tables): one CSV each in the run's directory, FILE.csv with a time
// column and the table's columns, a row whenever probes.csv gets one. Resumed with the run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/state_stream.h"
#include "framework/run/metrics_log.h"
#include "framework/world/world.h"

namespace upf {

class SolverTableLogs {
 public:
  // The world's solvers' tables; a file name met twice gets "_2", "_3" ... after it.
  SolverTableLogs(const World& world, const std::filesystem::path& out_dir, bool resuming);

  // The files the constructor makes, "FILE.csv" relative to the output directory, in order.
  static std::vector<std::string> file_names(const World& world);

  bool empty() const { return tables_.empty(); }
  // A row of each table from `state` at `time`; none from a state that lacks what they need.
  void add(const Particles& state, double time);
  void save_state(StateWriter& out);
  void restore_state(StateReader& in);

 private:
  struct Table {
    const Solver* solver;
    std::size_t index;    // among the solver's tables
    std::size_t columns;  // after time
    ProbeLog log;
  };
  const World& world_;
  std::vector<Table> tables_;
};

}  // namespace upf
