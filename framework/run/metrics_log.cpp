#include "framework/run/metrics_log.h"

#include <cmath>
#include <utility>

#include "framework/core/deterministic_sum.h"
#include "framework/core/errors.h"
#include "framework/output/resumed_log.h"
#include "framework/particles/kinetic_energy.h"

namespace upf {

double kinetic_energy(const Particles& particles, const CpuExecutor& exec) {
  return block_sum(exec, particles.size(),
                   KineticEnergyValue{particles.mass.data(), particles.velocity.data()});
}

namespace {
std::string metrics_header(const std::vector<std::string>& stages, bool sources,
                           bool viscosity_solve) {
  std::string h =
      "step,t,dt,iterations,avg_density_error,max_density_error,kinetic_energy,"
      "n_liquid,n_rigid,n_granular,n_frozen,";
  if (sources) h += "mass_in_kg,mass_out_kg,";
  if (viscosity_solve) h += "viscosity_iterations,";
  h += "neighbour_ms";
  for (const auto& s : stages) h += ',' + s + "_ms";
  return h + ",wall_ms\n";
}
std::string probes_header(const std::vector<std::string>& names) {
  std::string h = "t";
  for (const auto& n : names) h += ',' + n;
  return h + '\n';
}
}  // namespace

MetricsLog::MetricsLog(const std::filesystem::path& path, std::vector<std::string> stages,
                       bool resuming, bool sources, bool viscosity_solve)
    : log_(path, metrics_header(stages, sources, viscosity_solve), resuming),
      stages_(std::move(stages)),
      sources_(sources),
      viscosity_solve_(viscosity_solve) {}

void MetricsLog::add(const StepMetrics& m, const StepReport& r) {
  std::ostream& out = log_.out();
  out << m.step << ',' << m.time << ',' << r.dt << ',' << r.solver.iterations << ','
      << r.solver.avg_density_error << ',' << r.solver.max_density_error << ',' << m.kinetic_energy;
  for (std::size_t c : m.count_by_type) out << ',' << c;
  if (sources_) out << ',' << r.sources.mass_added << ',' << r.sources.mass_removed;
  if (viscosity_solve_) out << ',' << r.solver.viscosity_iterations;
  out << ',' << r.neighbour_ms;
  for (const auto& s : stages_) {
    double ms = 0;
    for (const auto& [name, v] : r.stage_ms)
      if (name == s) ms += v;
    out << ',' << ms;
  }
  out << ',' << r.total_ms << '\n';
}

void MetricsLog::save_state(StateWriter& out) {
  out.put(std::uint64_t(stages_.size()));
  for (const auto& s : stages_) out.put_string(s);
  log_.save_state(out);
}

void MetricsLog::restore_state(StateReader& in) {
  const auto n = in.get<std::uint64_t>();
  if (n > in.remaining()) in.fail("more metrics columns than the file can hold");
  std::vector<std::string> saved(static_cast<std::size_t>(n));
  for (auto& s : saved) s = in.get_string();
  in.expect(saved == stages_, "the metrics columns (the solvers' stages)");
  log_.restore_state(in);
}

void MetricsLog::flush() {
  log_.flush();
}

ProbeLog::ProbeLog(const std::filesystem::path& path, const std::vector<std::string>& names,
                   bool resuming)
    : log_(path, probes_header(names), resuming) {}

void ProbeLog::add(double time, const std::vector<double>& values) {
  std::ostream& out = log_.out();
  out << time;
  for (double v : values) {
    if (std::isnan(v)) {
      out << ",nan";
    } else {
      out << ',' << v;
    }
  }
  out << '\n';
  log_.flush();
}

void ProbeLog::save_state(StateWriter& out) {
  log_.save_state(out);
}

void ProbeLog::restore_state(StateReader& in) {
  log_.restore_state(in);
}

}  // namespace upf
