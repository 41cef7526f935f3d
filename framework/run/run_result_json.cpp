#include "framework/run/run_result_json.h"

#include <cmath>

namespace upf {

namespace {
nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}
}  // namespace

nlohmann::json run_result_json(const RunResult& r) {
  nlohmann::json j;
  j["status"] = r.status;
  if (!r.failure.empty()) j["failure"] = r.failure;
  j["threads"] = r.threads;
  j["mean_threads"] = r.mean_threads;
  j["steps"] = r.steps;
  j["simulated_time_s"] = r.simulated_time;
  j["wall_time_s"] = r.wall_seconds;
  j["particles"] = {{"liquid", r.liquid_particles}, {"total", r.total_particles}};
  j["frames"] = r.frames;
  j["mean_dt_s"] = r.mean_dt;
  j["mean_pressure_iterations"] = r.mean_iterations;
  j["max_pressure_iterations"] = r.max_iterations;
  j["mean_avg_density_error"] = finite_or_null(r.mean_avg_density_error);
  j["max_density_error"] = finite_or_null(r.max_density_error);
  j["fluid_particle_steps_per_second"] = r.fluid_particle_steps_per_second;
  j["wall_seconds_per_simulated_second"] =
      r.simulated_time > 0 ? r.wall_seconds / r.simulated_time : 0.0;
  nlohmann::json probes = nlohmann::json::object();
  for (const auto& [name, value] : r.final_probes) probes[name] = finite_or_null(value);
  j["final_probes"] = probes;
  return j;
}

}  // namespace upf
