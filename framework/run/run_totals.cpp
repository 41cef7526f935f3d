#include "framework/run/run_totals.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "framework/core/state_stream.h"
#include "framework/output/atomic_file.h"
#include "framework/run/run_result_json.h"

namespace upf {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Which solver moves each material, with its parameters: shows what `--solver` chose.
nlohmann::json materials_json(const SceneDescription& scene) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& m : scene.materials) {
    nlohmann::json& j = out[m.name];
    j["type"] = std::string(to_string(m.type));
    j["solver"] = m.solver.empty() ? nlohmann::json(nullptr) : nlohmann::json(m.solver);
    if (!m.solver.empty()) j["solver_params"] = m.solver_params.all();
  }
  return out;
}

}  // namespace

void RunTotals::add_stage(const std::string& name, double ms) {
  for (auto& [n, v] : stages_)
    if (n == name) {
      v.push_back(ms);
      return;
    }
  stages_.push_back({name, {ms}});
}

void RunTotals::add_step(const StepReport& r, RunResult& result, std::size_t liquid) {
  step_ms_.push_back(r.total_ms);
  sum_liquid_ += double(liquid);
  add_stage("neighbours", r.neighbour_ms);
  for (const auto& [name, ms] : r.stage_ms) add_stage(name, ms);
  sum_dt_ += r.dt;
  sum_iterations_ += r.solver.iterations;
  sum_avg_error_ += r.solver.avg_density_error;
  result.max_iterations = std::max(result.max_iterations, r.solver.iterations);
  result.max_density_error = std::max(result.max_density_error, r.solver.max_density_error);
}

void RunTotals::finish(RunResult& result) const {
  // Means over the steps that were recorded: an unstable run's failed step counts in `steps`
  // but has no figures.
  if (const double recorded = double(step_ms_.size()); recorded > 0) {
    result.mean_dt = sum_dt_ / recorded;
    result.mean_iterations = sum_iterations_ / recorded;
    result.mean_avg_density_error = sum_avg_error_ / recorded;
  }
  double compute_s = 0;
  for (double ms : step_ms_) compute_s += ms / 1000.0;
  if (compute_s > 0) result.fluid_particle_steps_per_second = sum_liquid_ / compute_s;
}

void RunTotals::write_summary(const std::filesystem::path& path, const SceneDescription& scene,
                              const RunResult& result) const {
  nlohmann::json j = run_result_json(result);
  j["scene"] = scene.name;
  j["source"] = scene.source.string();
  j["materials"] = materials_json(scene);
  j["median_step_ms"] = median(step_ms_);
  nlohmann::json stage_json = nlohmann::json::object();
  for (const auto& [name, values] : stages_) stage_json[name] = median(values);
  j["median_stage_ms"] = stage_json;
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

void RunTotals::save_state(StateWriter& out, const RunResult& r, double wall_seconds) const {
  out.put_vector(step_ms_);
  out.put(std::uint64_t(stages_.size()));
  for (const auto& [name, v] : stages_) {
    out.put_string(name);
    out.put_vector(v);
  }
  out.put(sum_dt_);
  out.put(sum_iterations_);
  out.put(sum_avg_error_);
  out.put(sum_liquid_);
  out.put(wall_seconds);
  out.put(std::int32_t(r.max_iterations));
  out.put(r.max_density_error);
  out.put(std::uint64_t(r.final_probes.size()));
  for (const auto& [name, value] : r.final_probes) {
    out.put_string(name);
    out.put(value);
  }
}

void RunTotals::restore_state(StateReader& in, RunResult& r) {
  in.get_vector(step_ms_);
  const auto n = in.get<std::uint64_t>();
  if (n > in.remaining()) in.fail("more stages than the file can hold");
  stages_.resize(std::size_t(n));
  for (auto& [name, v] : stages_) {
    name = in.get_string();
    in.get_vector(v);
  }
  sum_dt_ = in.get<double>();
  sum_iterations_ = in.get<double>();
  sum_avg_error_ = in.get<double>();
  sum_liquid_ = in.get<double>();
  wall_seconds_before_ = in.get<double>();
  r.max_iterations = in.get<std::int32_t>();
  r.max_density_error = in.get<double>();
  const auto probes = in.get<std::uint64_t>();
  if (probes > in.remaining()) in.fail("more probes than the file can hold");
  r.final_probes.resize(std::size_t(probes));
  for (auto& [name, value] : r.final_probes) {
    name = in.get_string();
    value = in.get<double>();
  }
}

}  // namespace upf
