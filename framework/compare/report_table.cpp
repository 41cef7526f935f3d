#include "framework/compare/report_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace upf {

namespace {
double wall_per_simulated_second(const RunResult& r) {
  return r.simulated_time > 0 ? r.wall_seconds / r.simulated_time : std::nan("");
}
}  // namespace

std::string format_number(double value, int digits) {
  if (!std::isfinite(value)) return "n/a";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string status_text(const CompareRow& row) {
  if (!row.unstable()) return row.result.status;
  return "unstable at t = " + format_number(row.result.simulated_time) + " s";
}

ReportTable make_report_table(const Comparison& c) {
  ReportTable t;
  t.header = {"solver",
              "status",
              "steps",
              "mean dt [s]",
              "mean iterations",
              "avg density error [%]",
              "max density error [%]",
              "wall s / sim s",
              "particle-steps/s"};
  for (std::size_t i = 0; i < c.probes.size(); ++i) t.header.push_back(c.probe_label(i));
  for (const auto& row : c.rows) {
    const RunResult& r = row.result;
    std::vector<std::string> cells = {row.name,
                                      status_text(row),
                                      std::to_string(r.steps),
                                      format_number(r.mean_dt),
                                      format_number(r.mean_iterations, 3),
                                      format_number(100.0 * r.mean_avg_density_error, 3),
                                      format_number(100.0 * r.max_density_error, 3),
                                      format_number(wall_per_simulated_second(r), 3),
                                      format_number(r.fluid_particle_steps_per_second, 3)};
    // Final probe values by name: every row has the scene's probes, in the scene's order.
    for (const auto& name : c.probes) {
      double value = std::nan("");
      for (const auto& [n, v] : r.final_probes)
        if (n == name) value = v;
      cells.push_back(format_number(value));
    }
    t.rows.push_back(std::move(cells));
  }
  return t;
}

std::string format_text_table(const ReportTable& table) {
  std::vector<std::size_t> width(table.header.size(), 0);
  auto widen = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size() && i < width.size(); ++i)
      width[i] = std::max(width[i], cells[i].size());
  };
  widen(table.header);
  for (const auto& r : table.rows) widen(r);
  std::string out;
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size() && i < width.size(); ++i) {
      if (i) out += "  ";
      out += cells[i];
      if (i + 1 < cells.size()) out.append(width[i] - cells[i].size(), ' ');
    }
    out += '\n';
  };
  line(table.header);
  std::vector<std::string> rule;
  for (std::size_t w : width) rule.emplace_back(w, '-');
  line(rule);
  for (const auto& r : table.rows) line(r);
  return out;
}

std::vector<std::pair<std::string, std::string>> report_facts(const Comparison& c) {
  return {{"scene", c.scene + " (" + c.source + ")"},
          {"particles", std::to_string(c.liquid_particles) + " liquid, " +
                            std::to_string(c.total_particles) + " in total"},
          {"threads", std::to_string(c.threads)},
          {"end time", format_number(c.end_time) + " s"},
          {"date", c.date}};
}

std::vector<std::pair<std::string, std::string>> column_notes() {
  return {
      {"status", "completed, or unstable at the simulated time the failing step reached"},
      {"steps", "time steps taken (up to the failure for an unstable run)"},
      {"mean dt [s]", "mean time step"},
      {"mean iterations", "mean pressure (or constraint) iterations per step"},
      {"avg density error [%]", "mean over steps of the average relative compression"},
      {"max density error [%]", "largest relative compression of any particle in any step"},
      {"wall s / sim s", "wall-clock seconds per simulated second (lower is faster)"},
      {"particle-steps/s", "liquid particles x steps per second of stepping (higher is faster)"},
      {"probes", "the last value each probe recorded (n/a: the probe saw no liquid)"},
  };
}

}  // namespace upf
