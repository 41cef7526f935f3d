#include "framework/compare/compare_plan_file.h"

#include <cmath>
#include <fstream>

#include "framework/core/errors.h"
#include "framework/core/file_name.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace {

constexpr int kPlanFormat = 1;

nlohmann::json read_json_file(const std::filesystem::path& path, const std::string& missing) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), missing);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string(), std::string("not valid JSON: ") + e.what());
  }
}

// j[key] as T, or an InputError naming the file and the key.
template <class T>
T field(const nlohmann::json& j, const char* key, const std::filesystem::path& path) {
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ":/" + key, std::string("missing or malformed: ") + e.what());
  }
}

double number_or_nan(const nlohmann::json& j, const char* key, const std::filesystem::path& path) {
  if (j.contains(key) && j.at(key).is_null()) return std::nan("");
  return field<double>(j, key, path);
}

nlohmann::json runs_json(const std::vector<PlannedRun>& runs) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : runs) j.push_back({{"name", r.name}, {"solver", r.solver}, {"set", r.sets}});
  return j;
}

}  // namespace

void write_compare_plan(const std::filesystem::path& out_dir, const ComparePlanFile& plan) {
  nlohmann::json j = {{"format", kPlanFormat},
                      {"date", plan.date},
                      {"scene_file", plan.scene_file.string()},
                      {"scene", plan.scene},
                      {"runs", runs_json(plan.runs)},
                      {"end_time_s", plan.end_time ? nlohmann::json(*plan.end_time) : nullptr},
                      {"threads", plan.threads},
                      {"write_frames", plan.write_frames}};
  ensure_directory(out_dir);
  write_file_atomically(out_dir / kComparePlanFile,
                        [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

ComparePlanFile read_compare_plan(const std::filesystem::path& out_dir) {
  const std::filesystem::path path = out_dir / kComparePlanFile;
  const nlohmann::json j = read_json_file(
      path, "no comparison planned here: make one with upf compare SCENE --plan --out " +
                out_dir.string());
  if (!j.is_object() || field<int>(j, "format", path) != kPlanFormat)
    throw InputError(path.string() + ":/format", "a plan of another upf version (format " +
                                                     std::to_string(kPlanFormat) +
                                                     " expected): plan the comparison again");
  ComparePlanFile plan;
  plan.date = field<std::string>(j, "date", path);
  plan.scene_file = field<std::string>(j, "scene_file", path);
  plan.scene = j.at("scene");
  const nlohmann::json runs = field<nlohmann::json>(j, "runs", path);
  if (!runs.is_array()) throw InputError(path.string() + ":/runs", "not an array of runs");
  for (const auto& r : runs) {
    plan.runs.push_back({field<std::string>(r, "name", path), field<std::string>(r, "solver", path),
                         field<std::vector<std::string>>(r, "set", path)});
    // The name becomes the run's folder under OUT/: a hand-edited "../x" or "/tmp/x" must not
    // send a task's files outside it, nor two tasks into one folder.
    const std::string& name = plan.runs.back().name;
    const std::string where =
        path.string() + ":/runs/" + std::to_string(plan.runs.size() - 1) + "/name";
    check_file_name(name, where);
    for (std::size_t k = 0; k + 1 < plan.runs.size(); ++k)
      if (plan.runs[k].name == name)
        throw InputError(where, "'" + name + "' is also the name of run " + std::to_string(k) +
                                    ": the two would share a folder");
  }
  if (!j.contains("end_time_s") || !j["end_time_s"].is_null())
    plan.end_time = field<double>(j, "end_time_s", path);
  plan.threads = field<int>(j, "threads", path);
  plan.write_frames = field<bool>(j, "write_frames", path);
  if (plan.runs.empty()) throw InputError(path.string() + ":/runs", "no run in the plan");
  return plan;
}

CompareRow read_compare_row(const std::filesystem::path& out_dir, const PlannedRun& run,
                            const std::vector<std::string>& probes) {
  const std::filesystem::path path = out_dir / run.name / "summary.json";
  const nlohmann::json j = read_json_file(path, "the run '" + run.name + "' has not finished");
  RunResult r;
  r.status = field<std::string>(j, "status", path);
  if (r.status == "interrupted")
    throw InputError(path.string(), "the run '" + run.name +
                                        "' was interrupted: resume it with upf run --resume " +
                                        (out_dir / run.name).string());
  if (j.contains("failure") && j["failure"].is_string()) r.failure = j["failure"];
  r.threads = field<int>(j, "threads", path);
  // Summaries of builds before it had no mean_threads: they kept every thread.
  r.mean_threads =
      j.contains("mean_threads") ? field<double>(j, "mean_threads", path) : double(r.threads);
  r.steps = field<std::uint64_t>(j, "steps", path);
  r.simulated_time = field<double>(j, "simulated_time_s", path);
  r.wall_seconds = field<double>(j, "wall_time_s", path);
  const nlohmann::json particles = field<nlohmann::json>(j, "particles", path);
  r.liquid_particles = field<std::size_t>(particles, "liquid", path);
  r.total_particles = field<std::size_t>(particles, "total", path);
  r.frames = field<int>(j, "frames", path);
  r.mean_dt = field<double>(j, "mean_dt_s", path);
  r.mean_iterations = field<double>(j, "mean_pressure_iterations", path);
  r.max_iterations = field<int>(j, "max_pressure_iterations", path);
  r.mean_avg_density_error = number_or_nan(j, "mean_avg_density_error", path);
  r.max_density_error = number_or_nan(j, "max_density_error", path);
  r.fluid_particle_steps_per_second = field<double>(j, "fluid_particle_steps_per_second", path);
  const nlohmann::json final_probes = field<nlohmann::json>(j, "final_probes", path);
  for (const auto& name : probes)
    r.final_probes.emplace_back(name, final_probes.contains(name)
                                          ? number_or_nan(final_probes, name.c_str(), path)
                                          : std::nan(""));
  return {run.solver, std::move(r), run.name};
}

}  // namespace upf
