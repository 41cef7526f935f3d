#include "commands.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>

#include "app_registry.h"
#include "checkpoint_options.h"
#include "device/device_pipelines.h"
#include "framework/checkpoint/checkpoint_file.h"
#include "framework/compare/compare_plan_file.h"
#include "framework/compare/compare_report.h"
#include "framework/compare/comparison.h"
#include "framework/compare/report_table.h"
#include "framework/core/errors.h"
#include "framework/output/vdb_frame_writers.h"
#include "framework/run/output_fields.h"
#include "framework/run/simulation_run.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_overrides.h"
#include "framework/scene/scene_reader.h"
#include "framework/scene/solver_override.h"
#include "framework/solver/registry.h"
#include "interrupt_signal.h"
#include "option_checks.h"
#include "output_estimate_report.h"
#include "progress.h"
#ifdef UPF_HAS_MPI
#include "mpi_run.h"
#endif

namespace upf::app {

namespace {
std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the scene file");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
// A scene file as it will run: read, the --set overrides applied, checked; and its text (the
// file's own bytes, or the overridden document) for scene.json and the checkpoint.
struct LoadedScene {
  SceneDescription scene;
  std::string text;
};
LoadedScene load_with_overrides(const std::string& file, const std::vector<std::string>& sets,
                                const Registry& registry) {
  if (sets.empty()) {
    SceneDescription scene = load_scene_file(file, registry);
    return {std::move(scene), read_text(file)};
  }
  nlohmann::json document = read_scene_json(file);
  std::vector<SceneOverride> overrides;
  for (const std::string& s : sets) overrides.push_back(parse_override(s));
  apply_overrides(document, overrides);
  SceneDescription scene = read_scene(document, registry, file);
  return {std::move(scene), document.dump(2) + "\n"};
}
}  // namespace

int run_command(const RunArgs& args) {
  const Registry registry = make_app_registry();
  // What to run: the scene file and the options given, or all of it from the checkpoint.
  ResumableRun run;
  std::filesystem::path out_dir = args.out_dir;
  SceneDescription scene;
  if (!args.resume.empty()) {
    out_dir = args.resume;
    const std::string where = (out_dir / kCheckpointFileName).string();
    run = from_header(read_checkpoint_header(out_dir), where);
    // --end may move the end: a stopped run can be taken further than first planned.
    if (args.end_time) run.end_time = args.end_time;
    const nlohmann::json document = nlohmann::json::parse(run.scene_text, nullptr, false);
    if (document.is_discarded()) throw InputError(where, "the checkpoint's scene is not JSON");
    scene = read_scene(document, registry, run.scene_source);
  } else {
    LoadedScene loaded = load_with_overrides(args.scene, args.sets, registry);
    run.scene_text = std::move(loaded.text);
    run.scene_source = args.scene;
    run.solver = args.solver;
    run.end_time = args.end_time;
    run.no_frames = args.no_frames;
    run.checkpoint_every = args.checkpoint_every;
    scene = std::move(loaded.scene);
    if (out_dir.empty()) out_dir = std::filesystem::path("out") / scene.name;
  }
  if (!run.solver.empty()) scene = with_solver(scene, registry, run.solver);
  if (args.render && run.no_frames)
    throw InputError("--render", "there are no frames to draw: the run has --no-frames");
  RunOptions options;
  options.out_dir = out_dir;
  options.threads = args.threads;
  options.follow_free_cores = !args.fixed_threads;
  options.end_time = run.end_time;
  options.write_frames = !run.no_frames;
  if (!run.checkpoint_every.empty())
    options.checkpoint = parse_checkpoint_every(run.checkpoint_every);
  options.checkpoint_header = to_header(run);
  options.scene_text = run.scene_text;
  options.vdb_writers = vdb_frame_writers();
  options.resume = !args.resume.empty();
  options.overwrite = args.overwrite;
  // Not kept in the checkpoint: every device gives the same bits, so a run may resume on another.
  const std::string device = args.device.value_or(scene.device);
  const std::string device_where =
      args.device ? std::string("--device") : scene.source.string() + ":/device";
  if (device != "cpu")
    options.make_device = [device, device_where](const World& world) {
      return make_device_pipeline(device, world, device_where);
    };
#ifdef UPF_HAS_MPI
  if (args.split_over_ranks) options.make_domain = mpi_domain_maker(args.rebalance_every);
#endif
  // Ranks other than 0 run silently: rank 0 reports for all of them.
  const bool quiet = args.quiet || args.rank != 0;
  InterruptSignal interrupt;
  options.stop_requested = [&] { return interrupt.requested(); };
  ProgressReporter progress(stderr);
  if (!quiet) options.on_progress = [&](const RunProgress& p) { progress.update(p); };
  options.on_output_estimate = [&](const OutputEstimate& e) {
    report_output_estimate(e, scene, quiet, stderr);
  };
  RunResult r;
  try {
    r = run_simulation(scene, registry, options);
  } catch (...) {
    progress.finish();
    throw;
  }
  progress.finish();
  const std::string out = options.out_dir.string();
  if (args.rank != 0)
    return r.status == "interrupted" ? static_cast<int>(ExitCode::Interrupted) : 0;
  if (r.already_complete) {
    std::printf(
        "%s: the run in %s is already complete at t = %.4f s (step %llu); nothing to do.\n"
        "extend it with: upf run --resume %s --end T (T > %.4f)\n",
        scene.name.c_str(), out.c_str(), r.simulated_time, static_cast<unsigned long long>(r.steps),
        out.c_str(), r.simulated_time);
    return 0;
  }
  if (r.status == "interrupted") {
    std::fprintf(stderr,
                 "interrupted at t = %.4f s (step %llu); checkpoint and summary written.\n"
                 "resume with: upf run --resume %s\n",
                 r.simulated_time, static_cast<unsigned long long>(r.steps), out.c_str());
    return static_cast<int>(ExitCode::Interrupted);
  }
  std::printf(
      "%s: %llu steps, %.3f s simulated in %.2f s wall, %zu liquid particles, "
      "%.3g fluid particle-steps/s, mean %.2f solver iterations per step (pressure iterations, "
      "DEM sub-steps)\n",
      scene.name.c_str(), static_cast<unsigned long long>(r.steps), r.simulated_time,
      r.wall_seconds, r.liquid_particles, r.fluid_particle_steps_per_second, r.mean_iterations);
  std::printf("output: %s (particles.pvd, metrics.csv, probes.csv, summary.json)\n", out.c_str());
  if (r.replaced_files > 0)
    std::printf("(it replaced an earlier run there: %zu of its files were removed first)\n",
                r.replaced_files);
  if (args.render) {
    RenderArgs render = args.render_args;
    render.run_dir = out;
    render.threads = args.threads;
    render.quiet = args.quiet;
    return render_command(render);
  }
  return 0;
}

namespace {
// --plot-script, else $UPF_PLOT_SCRIPT, else the script in the source tree this binary was built
// from (a compile definition), so a build directory works wherever it is.
std::filesystem::path plot_script(const CompareArgs& args) {
  if (!args.plot_script.empty()) return args.plot_script;
  if (const char* env = std::getenv("UPF_PLOT_SCRIPT"); env && *env) return env;
  return UPF_PLOT_SCRIPT;
}

// The report of `comparison` into its directory and the table on standard output; exit code 1
// when the plots are missing.
int report_comparison(const Comparison& comparison, const std::filesystem::path& out_dir,
                      const CompareArgs& args) {
  const PlotOutcome plots = write_compare_report(comparison, out_dir, plot_script(args));
  std::printf("%s", format_text_table(make_report_table(comparison)).c_str());
  const std::string out = out_dir.string();
  std::printf("report: %s/report.md, %s/report.html, %s/report.json\n", out.c_str(), out.c_str(),
              out.c_str());
  if (!plots.ok) {
    std::fprintf(stderr, "error: the plots are missing: %s\n(the tables were written)\n",
                 plots.error.c_str());
    return static_cast<int>(ExitCode::Failure);
  }
  return 0;
}

// `document` with `sets` (--set or --vary arguments) applied.
nlohmann::json with_sets(nlohmann::json document, const std::vector<std::string>& sets) {
  std::vector<SceneOverride> overrides;
  for (const std::string& s : sets) overrides.push_back(parse_override(s));
  apply_overrides(document, overrides);
  return document;
}

// The runs of a comparison or sweep: per combination of the --vary values (the first axis
// slowest), one run per solver, each named after its solver and values.
struct ComparisonRuns {
  nlohmann::json document;  // the scene file's document with --set applied
  std::vector<SolverRunPlan> runs;
  std::vector<PlannedRun> planned;  // the same runs, as plan.json holds them
};
// A swept solver parameter reaches only the solver the scene names for that material: another
// solver of the comparison runs with its own defaults (with_solver), the same at every value.
void warn_unreached_sweeps(const nlohmann::json& document, const std::vector<SweepAxis>& axes,
                           const std::vector<std::string>& solvers) {
  for (const auto& axis : axes) {
    const std::string prefix = "/materials/";
    const auto solver_at = axis.pointer.find("/solver/");
    if (axis.pointer.rfind(prefix, 0) != 0 || solver_at == std::string::npos) continue;
    const nlohmann::json::json_pointer where(axis.pointer.substr(0, solver_at + 7));
    if (!document.contains(where)) continue;
    const nlohmann::json& named = document.at(where);
    const std::string scene_solver =
        named.is_string() ? named.get<std::string>() : named.value("name", std::string());
    for (const auto& s : solvers)
      if (s != scene_solver)
        std::fprintf(stderr,
                     "warning: --vary %s changes %s's parameters; %s runs with its own defaults, "
                     "the same at every value\n",
                     axis.pointer.c_str(), scene_solver.c_str(), s.c_str());
  }
}

ComparisonRuns comparison_runs(const CompareArgs& args, const Registry& registry) {
  ComparisonRuns c;
  c.document = with_sets(read_scene_json(args.scene), args.sets);
  const SceneDescription base = read_scene(c.document, registry, args.scene);
  const std::vector<std::string> solvers =
      args.solvers_given ? args.solvers : solvers_for_scene(base, registry);
  std::vector<SweepAxis> axes;
  for (const auto& v : args.vary) axes.push_back(parse_sweep_axis(v));
  check_sweep_axes(axes);
  warn_unreached_sweeps(c.document, axes, solvers);
  std::vector<std::string> names;
  for (const auto& sets : sweep_combinations(axes)) {
    const SceneDescription scene =
        sets.empty() ? base : read_scene(with_sets(c.document, sets), registry, args.scene);
    for (SolverRunPlan& run : plan_comparison(scene, registry, solvers)) {
      run.name = sweep_run_name(run.solver, axes, sets);
      names.push_back(run.name);
      c.planned.push_back({run.name, run.solver, sets});
      c.runs.push_back(std::move(run));
    }
  }
  // The names are folders under --out: one plain name each, no two alike (a value with a control
  // character, or too long a name, is caught here).
  check_run_names(names, args.vary.empty() ? "--solvers" : "--vary");
  return c;
}

// The runs of OUT/plan.json, checked again against this build's solvers.
std::vector<SolverRunPlan> planned_runs(const ComparePlanFile& plan,
                                        const std::filesystem::path& out_dir,
                                        const Registry& registry) {
  const std::string where = (out_dir / kComparePlanFile).string() + ":/runs";
  std::vector<SolverRunPlan> runs;
  for (const PlannedRun& p : plan.runs) {
    const SceneDescription scene =
        read_scene(with_sets(plan.scene, p.sets), registry, plan.scene_file.string());
    SolverRunPlan run = plan_comparison(scene, registry, {p.solver}, where).front();
    run.name = p.name;
    runs.push_back(std::move(run));
  }
  return runs;
}

CompareOptions split_options(const ComparePlanFile& plan, const CompareArgs& args) {
  // --threads is checked by the command line; the plan's own count comes from a file.
  if (plan.threads < 0 || plan.threads > kMaxThreads)
    throw InputError(
        (std::filesystem::path(args.out_dir) / kComparePlanFile).string() + ":/threads",
        std::to_string(plan.threads) + " threads: allowed 0 (all) to " +
            std::to_string(kMaxThreads));
  CompareOptions options;
  options.out_dir = args.out_dir;
  options.vdb_writers = vdb_frame_writers();
  options.threads = args.threads > 0 ? args.threads : plan.threads;
  options.follow_free_cores = !args.fixed_threads;
  options.end_time = plan.end_time;
  options.write_frames = plan.write_frames;
  return options;
}

// `upf compare --task K`: the plan's run K, as the one-process comparison runs it.
int compare_task_command(const CompareArgs& args) {
  const Registry registry = make_app_registry();
  const ComparePlanFile plan = read_compare_plan(args.out_dir);
  const auto runs = planned_runs(plan, args.out_dir, registry);
  const int k = *args.task;
  if (k < 0 || std::size_t(k) >= runs.size())
    throw InputError(
        "--task", "task " + std::to_string(k) + " is outside the plan's " +
                      std::to_string(runs.size()) + " runs (0.." + std::to_string(runs.size() - 1) +
                      ") in " + (std::filesystem::path(args.out_dir) / kComparePlanFile).string());
  CompareOptions options = split_options(plan, args);
  std::optional<ProgressReporter> progress;
  if (!args.quiet) {
    std::fprintf(stderr, "[task %d of 0..%zu] %s\n", k, runs.size() - 1, runs[k].name.c_str());
    progress.emplace(stderr);
    options.on_progress = [&](const RunProgress& p) { progress->update(p); };
  }
  CompareRow row;
  try {
    row = run_compare_entry(runs[std::size_t(k)], registry, options);
  } catch (...) {
    if (progress) progress->finish();
    throw;
  }
  if (progress) progress->finish();
  std::printf("%s: %s (%.2f s wall) in %s\n", row.name.c_str(), status_text(row).c_str(),
              row.result.wall_seconds, (options.out_dir / row.name).string().c_str());
  return 0;
}

// `upf compare --collect`: the report of the plan's runs, once every one has finished.
int compare_collect_command(const CompareArgs& args) {
  const Registry registry = make_app_registry();
  const ComparePlanFile plan = read_compare_plan(args.out_dir);
  const auto runs = planned_runs(plan, args.out_dir, registry);
  const CompareOptions options = split_options(plan, args);
  Comparison comparison = start_comparison(runs, options);
  comparison.date = plan.date;
  std::vector<InputProblem> missing;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    try {
      add_compare_row(comparison,
                      read_compare_row(options.out_dir, plan.runs[k], comparison.probes));
    } catch (const InputError& e) {
      for (const auto& p : e.problems())
        missing.push_back({p.where, p.message + " (task " + std::to_string(k) + ")"});
    }
  }
  if (!missing.empty()) throw InputError(std::move(missing));
  return report_comparison(comparison, options.out_dir, args);
}

// `upf compare SCENE --plan`: OUT/plan.json, and how to run it.
int compare_plan_command(const CompareArgs& args, const ComparisonRuns& c) {
  const std::vector<SolverRunPlan>& runs = c.runs;
  ComparePlanFile plan;
  plan.scene_file = std::filesystem::absolute(args.scene);
  plan.scene = c.document;
  plan.runs = c.planned;
  plan.end_time = args.end_time;
  plan.threads = args.threads;
  plan.write_frames = !args.no_frames;
  plan.date = utc_now_iso8601();
  write_compare_plan(args.out_dir, plan);
  const std::string out = args.out_dir;
  std::printf("planned %zu runs in %s/%s:", runs.size(), out.c_str(), kComparePlanFile);
  for (std::size_t k = 0; k < runs.size(); ++k) std::printf(" %zu %s", k, runs[k].name.c_str());
  std::printf(
      "\nrun each (any order, any machine that sees %s):  upf compare --task K --out %s   "
      "(K = 0..%zu)\n"
      "as a Slurm job array:  sbatch --array=0-%zu scripts/slurm/compare-array.sbatch %s\n"
      "then the report:  upf compare --collect --out %s\n",
      out.c_str(), out.c_str(), runs.size() - 1, runs.size() - 1, out.c_str(), out.c_str());
  return 0;
}

void check_split_options(const CompareArgs& args) {
  const int modes = int(args.plan) + int(args.task.has_value()) + int(args.collect);
  if (modes > 1) throw InputError("upf compare", "give one of --plan, --task and --collect");
  if (args.task || args.collect) {
    const char* mode = args.task ? "--task" : "--collect";
    std::vector<InputProblem> problems;
    auto refuse = [&](bool given, const std::string& what) {
      if (given)
        problems.push_back({mode, what + " comes from the plan (" + std::string(kComparePlanFile) +
                                      "): leave it out, or plan again"});
    };
    refuse(!args.scene.empty(), "the scene");
    refuse(args.solvers_given, "--solvers");
    refuse(!args.sets.empty(), "--set");
    refuse(!args.vary.empty(), "--vary");
    refuse(args.end_time.has_value(), "--end");
    refuse(args.no_frames, "--no-frames");
    if (!problems.empty()) throw InputError(std::move(problems));
  } else if (args.scene.empty()) {
    throw InputError("upf compare", "give a scene file (or --task K / --collect with --out DIR)");
  }
}

}  // namespace

int compare_command(const CompareArgs& args) {
  check_split_options(args);
  if (args.task) return compare_task_command(args);
  if (args.collect) return compare_collect_command(args);
  const Registry registry = make_app_registry();
  const ComparisonRuns runs = comparison_runs(args, registry);
  if (args.plan) return compare_plan_command(args, runs);
  const std::vector<SolverRunPlan>& plan = runs.runs;

  CompareOptions options;
  options.out_dir = args.out_dir;
  options.vdb_writers = vdb_frame_writers();
  options.threads = args.threads;
  options.follow_free_cores = !args.fixed_threads;
  options.end_time = args.end_time;
  options.write_frames = !args.no_frames;
  // A fresh progress line per run: each run's clock starts at zero.
  std::optional<ProgressReporter> progress;
  if (!args.quiet) {
    options.on_run_start = [&](const SolverRunPlan& p, std::size_t i, std::size_t n) {
      std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, n, p.name.c_str());
      progress.emplace(stderr);
    };
    options.on_progress = [&](const RunProgress& p) { progress->update(p); };
    options.on_run_end = [&](const CompareRow& row) {
      progress->finish();
      std::fprintf(stderr, "%s: %s (%.2f s wall)\n", row.name.c_str(), status_text(row).c_str(),
                   row.result.wall_seconds);
    };
  }
  Comparison comparison;
  try {
    comparison = run_comparison(plan, registry, options);
  } catch (...) {
    if (progress) progress->finish();
    throw;
  }

  return report_comparison(comparison, options.out_dir, args);
}

int validate_command(const std::vector<std::string>& files, const std::vector<std::string>& sets) {
  const Registry registry = make_app_registry();
  int bad = 0;
  for (const auto& f : files) {
    try {
      const SceneDescription scene = load_with_overrides(f, sets, registry).scene;
      // Which fields exist is known once the solvers have declared theirs, and whether the
      // scene's device covers it once the world is built: then build and prepare the world as
      // `upf run` does before it writes, and check them (the device without touching a GPU).
      if (scene.output.fields || scene.device != "cpu") {
        const auto world = build_world(scene, registry, 0);
        world->prepare();
        if (scene.output.fields) check_output_fields(scene, world->particles());
        const std::string device_where = scene.source.string() + ":/device";
        check_device(scene.device, *world, device_where);
        // check_device knows the names and the solvers, not whether this machine has a usable
        // GPU: `upf run` would stop there, so validate asks as it does (and drops the pipeline).
        if (scene.device == "cuda") make_device_pipeline(scene.device, *world, device_where);
      }
      std::printf("%s: ok (%.0f particles)\n", f.c_str(), scene.estimated_particles());
    } catch (const InputError& e) {
      ++bad;
      std::fprintf(stderr, "%s: %zu problem%s\n", f.c_str(), e.problems().size(),
                   e.problems().size() == 1 ? "" : "s");
      for (const auto& p : e.problems())
        std::fprintf(stderr, "  %s: %s\n", p.where.c_str(), p.message.c_str());
    }
  }
  return bad ? static_cast<int>(ExitCode::BadInput) : 0;
}

}  // namespace upf::app
