#include "framework/compare/comparison.h"

#include <ctime>
#include <stdexcept>

#include "framework/run/probes.h"

namespace upf {

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

Comparison start_comparison(const std::vector<SolverRunPlan>& plan, const CompareOptions& options) {
  if (plan.empty()) throw std::invalid_argument("start_comparison: no solver to run");
  const SceneDescription& scene = plan.front().scene;
  Comparison c;
  c.scene = scene.name;
  c.source = scene.source.string();
  c.end_time = options.end_time.value_or(scene.world.time.end);
  c.date = utc_now_iso8601();
  for (const auto& p : scene.probes) {
    c.probes.push_back(p.name);
    c.probe_units.push_back(probe_unit(p.kind));
  }
  return c;
}

CompareRow run_compare_entry(const SolverRunPlan& entry, const Registry& registry,
                             const CompareOptions& options) {
  RunOptions run;
  run.out_dir = options.out_dir / entry.name;
  run.threads = options.threads;
  run.follow_free_cores = options.follow_free_cores;
  run.vdb_writers = options.vdb_writers;
  run.end_time = options.end_time;
  run.write_frames = options.write_frames;
  run.on_progress = options.on_progress;
  run.throw_on_instability = false;  // an unstable solver is a result of the comparison
  run.final_checkpoint = false;
  return {entry.solver, run_simulation(entry.scene, registry, run), entry.name};
}

void add_compare_row(Comparison& c, CompareRow row) {
  // Every run builds the same particles: any row gives the counts.
  c.liquid_particles = row.result.liquid_particles;
  c.total_particles = row.result.total_particles;
  c.threads = row.result.threads;
  c.rows.push_back(std::move(row));
}

Comparison run_comparison(const std::vector<SolverRunPlan>& plan, const Registry& registry,
                          const CompareOptions& options) {
  Comparison c = start_comparison(plan, options);
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (options.on_run_start) options.on_run_start(plan[i], i, plan.size());
    CompareRow row = run_compare_entry(plan[i], registry, options);
    if (options.on_run_end) options.on_run_end(row);
    add_compare_row(c, std::move(row));
  }
  return c;
}

}  // namespace upf
