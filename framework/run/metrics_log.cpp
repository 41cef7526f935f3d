#include "framework/run/metrics_log.h"

#include <cmath>
#include <utility>

#include "framework/core/deterministic_sum.h"
#include "framework/core/errors.h"
#include "framework/output/resumed_log.h"

namespace upf {

namespace {
std::ofstream open_log(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw OutputError("cannot write " + path.string());
  out.precision(9);
  return out;
}

void check(const std::ofstream& out, const std::filesystem::path& path) {
  if (!out) throw OutputError("writing " + path.string() + " failed (disk full?)");
}

// The log's length after a flush, for a checkpoint.
void save_length(StateWriter& out, std::ofstream& log, const std::filesystem::path& path) {
  log.flush();
  check(log, path);
  out.put(std::uint64_t(std::filesystem::file_size(path)));
}

// Cuts the log back to its length at the checkpoint and appends from there.
void restore_length(StateReader& in, std::ofstream& log, const std::filesystem::path& path) {
  const auto length = in.get<std::uint64_t>();
  std::error_code ec;
  const auto now = std::filesystem::file_size(path, ec);
  if (ec || now < length)
    in.fail(path.string() + " is shorter than at the checkpoint (" + std::to_string(length) +
            " bytes)");
  reopen_log_at(log, path, length);
  log.precision(9);
}
}  // namespace

namespace {
struct KineticEnergyValue {
  const Real* mass;
  const Vec3* velocity;
  double operator()(std::size_t i) const {
    return 0.5 * double(mass[i]) * double(squared_norm(velocity[i]));
  }
};
}  // namespace

double kinetic_energy(const Particles& particles, const CpuExecutor& exec) {
  return block_sum(exec, particles.size(),
                   KineticEnergyValue{particles.mass.data(), particles.velocity.data()});
}

MetricsLog::MetricsLog(const std::filesystem::path& path, std::vector<std::string> stages,
                       bool resuming)
    : path_(path), stages_(std::move(stages)) {
  if (resuming) return;
  out_ = open_log(path);
  out_ << "step,t,dt,iterations,avg_density_error,max_density_error,kinetic_energy,"
          "n_liquid,n_rigid,n_granular,n_frozen,neighbour_ms";
  for (const auto& s : stages_) out_ << ',' << s << "_ms";
  out_ << ",wall_ms\n";
}

void MetricsLog::add(const StepMetrics& m, const StepReport& r) {
  out_ << m.step << ',' << m.time << ',' << r.dt << ',' << r.solver.iterations << ','
       << r.solver.avg_density_error << ',' << r.solver.max_density_error << ','
       << m.kinetic_energy;
  for (std::size_t c : m.count_by_type) out_ << ',' << c;
  out_ << ',' << r.neighbour_ms;
  for (const auto& s : stages_) {
    double ms = 0;
    for (const auto& [name, v] : r.stage_ms)
      if (name == s) ms += v;
    out_ << ',' << ms;
  }
  out_ << ',' << r.total_ms << '\n';
}

void MetricsLog::save_state(StateWriter& out) {
  out.put(std::uint64_t(stages_.size()));
  for (const auto& s : stages_) out.put_string(s);
  save_length(out, out_, path_);
}

void MetricsLog::restore_state(StateReader& in) {
  const auto n = in.get<std::uint64_t>();
  if (n > in.remaining()) in.fail("more metrics columns than the file can hold");
  std::vector<std::string> saved(static_cast<std::size_t>(n));
  for (auto& s : saved) s = in.get_string();
  in.expect(saved == stages_, "the metrics columns (the solvers' stages)");
  restore_length(in, out_, path_);
}

void ProbeLog::save_state(StateWriter& out) {
  save_length(out, out_, path_);
}

void ProbeLog::restore_state(StateReader& in) {
  restore_length(in, out_, path_);
}

void MetricsLog::flush() {
  out_.flush();
  check(out_, path_);
}

ProbeLog::ProbeLog(const std::filesystem::path& path, const std::vector<std::string>& names,
                   bool resuming)
    : path_(path) {
  if (resuming) return;
  out_ = open_log(path);
  out_ << 't';
  for (const auto& n : names) out_ << ',' << n;
  out_ << '\n';
}

void ProbeLog::add(double time, const std::vector<double>& values) {
  out_ << time;
  for (double v : values) {
    if (std::isnan(v)) {
      out_ << ",nan";
    } else {
      out_ << ',' << v;
    }
  }
  out_ << '\n';
  out_.flush();
  check(out_, path_);
}

}  // namespace upf
