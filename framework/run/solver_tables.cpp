#include "framework/run/solver_tables.h"

#include <algorithm>

namespace upf {

std::vector<std::string> SolverTableLogs::file_names(const World& world) {
  std::vector<std::string> files;
  for (const auto& solver : world.solvers())
    for (const SolverTable& table : solver->tables(world)) {
      std::string file = table.file;
      for (int n = 2; std::find(files.begin(), files.end(), file + ".csv") != files.end(); ++n)
        file = table.file + "_" + std::to_string(n);
      files.push_back(file + ".csv");
    }
  return files;
}

SolverTableLogs::SolverTableLogs(const World& world, const std::filesystem::path& out_dir,
                                 bool resuming)
    : world_(world) {
  const std::vector<std::string> files = file_names(world);
  std::size_t k = 0;
  for (const auto& solver : world.solvers()) {
    const std::vector<SolverTable> tables = solver->tables(world);
    for (std::size_t t = 0; t < tables.size(); ++t, ++k)
      tables_.push_back({solver.get(), t, tables[t].columns.size(),
                         ProbeLog(out_dir / files[k], tables[t].columns, resuming)});
  }
}

void SolverTableLogs::add(const Particles& state, double time) {
  const Solver* rows_of = nullptr;
  std::vector<std::vector<double>> rows;
  for (Table& t : tables_) {
    if (t.solver != rows_of) {
      rows = t.solver->table_rows(world_, state);
      rows_of = t.solver;
    }
    if (t.index < rows.size() && rows[t.index].size() == t.columns) t.log.add(time, rows[t.index]);
  }
}

void SolverTableLogs::save_state(StateWriter& out) {
  out.put(std::uint32_t(tables_.size()));
  for (Table& t : tables_) t.log.save_state(out);
}

void SolverTableLogs::restore_state(StateReader& in) {
  in.expect(in.get<std::uint32_t>() == tables_.size(), "the solvers' tables");
  for (Table& t : tables_) t.log.restore_state(in);
}

}  // namespace upf
