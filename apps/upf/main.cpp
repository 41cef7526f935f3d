// upf: the command-line program. Thin: it parses arguments and calls the framework.
//   upf run SCENE [--out DIR] [--threads N] [--end T] [--quiet] [--solver NAME]
//           [--checkpoint-every 5m|0.5sim] [--set PTR=VALUE ...]
//           [--render [--color-by F] [--size WxH] ...]
//   upf run --resume DIR [--threads N] [--end T]
//   upf render RUN_DIR [--color-by F] [--size WxH] [--frames A:B] [--out DIR] [--no-video]
//   upf view SCENE_OR_RUN [--size WxH] [--threads N] [--play]
//            [--screenshot FILE.png [--exit-after N]]
//   upf compare SCENE [--solvers A,B,...] [--out DIR] [--threads N] [--end T] [--no-frames] [-q]
//   upf compare SCENE ... --plan; upf compare --task K --out DIR; upf compare --collect --out DIR
//   upf validate SCENE... [--set PTR=VALUE]
//   upf info [--markdown]
// Exit codes: 0 ok, 1 other failure (output, compare's plots), 2 bad input, 3 unstable run,
// 130 interrupted (Ctrl-C: a checkpoint was written, the run can be resumed).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "app_registry.h"
#include "commands.h"
#include "framework/core/errors.h"
#include "help_format.h"
#include "info_command.h"
#include "mpi_launch.h"
#include "option_checks.h"
#ifdef UPF_HAS_MPI
#include "mpi_run.h"
#endif
#include "render_command.h"
#include "viewer/viewer.h"

namespace {
// The options `run` and `compare` share, with the same meaning.
void add_run_controls(CLI::App& command, int& threads, bool& fixed_threads,
                      std::optional<double>& end_time, bool& quiet, bool& no_frames) {
  command.add_option("--threads,-j", threads, "CPU threads (default: all)")
      ->check(CLI::Range(1, upf::app::kMaxThreads));
  command.add_flag("--fixed-threads", fixed_threads,
                   "keep every thread while other processes take cores (by default a run uses "
                   "one thread per free core; the results are the same bits either way)");
  command.add_option("--end", end_time, "end time in seconds, overriding the scene's")
      ->check(upf::app::end_time_check());
  command.add_flag("--quiet,-q", quiet, "no progress output");
  command.add_flag("--no-frames", no_frames, "write metrics and probes only");
}
}  // namespace

int main(int argc, char** argv) {
  using upf::ExitCode;
  CLI::App app{
      "upf: unified particle framework (liquids, rigid bodies, granular media, frozen "
      "boundaries in one particle world)"};
  app.require_subcommand(1);
  // Set before the commands are added: each takes a copy of the app's formatter.
  app.formatter(std::make_shared<upf::app::PlainHelpFormatter>());
  app.footer(upf::app::main_help_footer());
  app.set_version_flag("--version", "upf 0.1.0");

  upf::app::RunArgs run_args;
  auto* run = app.add_subcommand("run", "run a scene: frames, metrics and probes into --out");
  run->footer(R"(
Examples:
  upf run samples/dam_break.json --out out/db --threads 2
  upf run samples/dam_break.json --solver dfsph --end 0.5 --no-frames
  upf run samples/dam_break.json --set /materials/water/viscosity=0.01 --set /time/end=2
  upf run samples/dam_break.json --checkpoint-every 5m      then: upf run --resume out/dam_break
  upf run samples/dam_break.json --render --color-by pressure
  upf run samples/dam_break.json --device cuda       on a GPU (omp: the same pipeline on the CPU)
  mpirun -n 4 upf run samples/dam_break.json         split over 4 MPI ranks (docs/mpi.md)

A new run into a directory that holds an earlier run removes the files that run wrote (its
upf_manifest.txt lists them) and nothing else. A non-empty directory without a manifest is
refused unless --overwrite is given. Symbolic links inside it are never followed.
Exit codes: 0 ok, 1 output failure, 2 bad input, 3 unstable (last good frame written),
130 interrupted by Ctrl-C (checkpoint written; --resume continues).)");
  auto* scene_option = run->add_option("scene", run_args.scene, "scene file (JSON)");
  auto* out_option =
      run->add_option("--out,-o", run_args.out_dir, "output directory (default out/<scene name>)")
          ->check(upf::app::non_empty_dir_check());
  add_run_controls(*run, run_args.threads, run_args.fixed_threads, run_args.end_time,
                   run_args.quiet, run_args.no_frames);
  auto* overwrite_option = run->add_flag(
      "--overwrite", run_args.overwrite,
      "write into a non-empty directory that no upf run recorded (no upf_manifest.txt): the "
      "files there at the names this run writes (particles.pvd, metrics.csv, probes.csv, "
      "summary.json, upf_scene.json, bodies.csv, body_forces.csv, dem_*_walls.csv, "
      "checkpoint.upfck, frames/frame_NNNNN.*, frames/surface_NNNNN.*, frames/bodies_NNNNN.vtp, "
      "frames/frozen.*) are replaced; nothing else is deleted");
  auto* solver_option =
      run->add_option("--solver", run_args.solver,
                      "move every material of the solver's particle type with this solver");
  auto* every_option = run->add_option(
      "--checkpoint-every", run_args.checkpoint_every,
      "write a checkpoint every DURATION: 300s, 5m, 2h (wall-clock) or 0.5sim (simulated "
      "seconds; bitwise reproducible even with rigid-body contacts). Ctrl-C always writes one");
  auto* set_option =
      run->add_option(
             "--set", run_args.sets,
             "override a scene value by JSON pointer, checked like the file and kept in the run's "
             "upf_scene.json: --set /materials/water/viscosity=0.01 (repeatable)")
          ->allow_extra_args(false);
  run->add_option("--resume", run_args.resume,
                  "continue the run in this output directory from its checkpoint, with the scene "
                  "and options it was started with (--end may move its end)")
      ->excludes(scene_option)
      ->excludes(out_option)
      ->excludes(overwrite_option)
      ->excludes(solver_option)
      ->excludes(every_option)
      ->excludes(set_option);
  run->add_option("--device", run_args.device,
                  "where the steps run (default: the scene's \"device\", else cpu): cpu, omp (the "
                  "GPU pipeline on the CPU's threads, bitwise the same results) or cuda; PCISPH, "
                  "IISPH, DFSPH, WCSPH or SPH with walls and bodies so far (no grains)");
  run->add_option("--rebalance-every", run_args.rebalance_every,
                  "started by mpirun -n P: new domain cuts every N steps (docs/mpi.md); results "
                  "do not depend on it")
      ->check(CLI::Range(0, 1000000));
  run->add_flag("--render", run_args.render,
                "draw a PNG of every frame (and an MP4 with ffmpeg) into OUT/render when done");
  add_render_options(*run, run_args.render_args);

  upf::app::RenderArgs render_args;
  auto* render = app.add_subcommand(
      "render", "draw a run's saved frames: one PNG per frame, and an MP4 with ffmpeg");
  render->footer(R"(
Examples:
  upf render out/dam_break                       pictures into out/dam_break/render/
  upf render out/dam_break --color-by pressure --frames 0:30 --size 1920x1080

Exit codes: 0 ok, 1 output failure, 2 bad input (no run there, unknown field).)");
  render->add_option("run_dir", render_args.run_dir, "the run's output directory")->required();
  render->add_option("--out,-o", render_args.out_dir, "picture directory (default RUN_DIR/render)")
      ->check(upf::app::non_empty_dir_check());
  render->add_option("--frames", render_args.frames,
                     "frame N, or frames A:B (either may be empty)");
  render->add_option("--threads,-j", render_args.threads, "CPU threads (default: all)")
      ->check(CLI::Range(1, upf::app::kMaxThreads));
  render->add_flag("--quiet,-q", render_args.quiet, "no progress output");
  add_render_options(*render, render_args);

  upf::app::CompareArgs compare_args;
  auto* compare = app.add_subcommand(
      "compare", "run a scene once per solver into OUT/<solver>/, then report and plot");
  compare->footer(R"(
Examples:
  upf compare samples/dam_break.json --solvers pcisph,dfsph,iisph --end 0.5 --threads 2
  upf compare samples/hydrostatic_tank.json --set /time/end=0.5 --no-frames
  upf compare samples/dam_break.json --solvers pcisph --vary /materials/water/solver/eta=0.01,0.002

Split over processes (a Slurm job array, GNU parallel; docs/compare.md):
  upf compare samples/dam_break.json --solvers pcisph,dfsph --out runs --plan
  upf compare --task 0 --out runs        (and --task 1, anywhere that sees runs/)
  upf compare --collect --out runs       the same report

Exit codes: 0 ok (an unstable solver gets its row), 1 plots missing, 2 bad input.)");
  compare->add_option("scene", compare_args.scene,
                      "scene file (JSON); not with --task or --collect, which read OUT/plan.json");
  auto* solvers =
      compare
          ->add_option("--solvers", compare_args.solvers,
                       "comma-separated solver names (default: every registered solver the "
                       "scene has particles for)")
          ->delimiter(',');
  compare->add_option("--out,-o", compare_args.out_dir, "output directory (default out/compare)")
      ->check(upf::app::non_empty_dir_check());
  add_run_controls(*compare, compare_args.threads, compare_args.fixed_threads,
                   compare_args.end_time, compare_args.quiet, compare_args.no_frames);
  compare->add_option("--plot-script", compare_args.plot_script,
                      "the plotting script (default: $UPF_PLOT_SCRIPT, else "
                      "scripts/plot_compare.py of the source tree)");
  compare
      ->add_option("--set", compare_args.sets,
                   "override a scene value by JSON pointer, as `upf run --set` (repeatable)")
      ->allow_extra_args(false);
  compare
      ->add_option("--vary", compare_args.vary,
                   "sweep a scene value: POINTER=V1,V2,... runs every solver at each value "
                   "(repeatable: every combination), each run named SOLVER,KEY=VALUE")
      ->allow_extra_args(false);
  compare->add_flag("--plan", compare_args.plan,
                    "write OUT/plan.json and run nothing: each run is then one --task");
  compare->add_option("--task", compare_args.task,
                      "run the plan's run K into OUT/<solver>/ (K from 0; a Slurm array's "
                      "$SLURM_ARRAY_TASK_ID)");
  compare->add_flag("--collect", compare_args.collect,
                    "write the report of the plan's runs once every one has finished");

  upf::viewer::ViewOptions view_options;
  auto* view = app.add_subcommand(
      "view", "an interactive window over a scene (stepped live) or a run's saved frames");
  view->footer(R"(
Examples:
  upf view samples/dam_break.json                stepped live
  upf view out/dam_break --play                  a run's saved frames

Exit codes: 0 ok, 1 no display or OpenGL, 2 bad input.)");
  view->add_option("input", view_options.input, "a scene file or a run's output directory")
      ->required();
  view->add_option("--size", view_options.size, "window size WIDTHxHEIGHT (default 1280x720)");
  view->add_option("--threads,-j", view_options.threads, "CPU threads (default: all)")
      ->check(CLI::Range(1, upf::app::kMaxThreads));
  view->add_option("--screenshot", view_options.screenshot,
                   "write the window's pixels to this PNG after --exit-after frames, then exit");
  view->add_option("--exit-after", view_options.exit_after,
                   "close after drawing N frames (default 3 with --screenshot)")
      ->check(CLI::Range(1, 1000000));
  view->add_flag("--play", view_options.play, "start playing");

  std::vector<std::string> validate_files;
  auto* validate = app.add_subcommand("validate", "check scene files; list every problem");
  validate->footer(R"(
Example:
  upf validate samples/*.json

Exit codes: 0 every scene valid, 2 a problem in some scene (each as file:/json/path: message).)");
  validate->add_option("scenes", validate_files, "scene files")->required();
  std::vector<std::string> validate_sets;
  validate
      ->add_option("--set", validate_sets,
                   "override a value by JSON pointer before checking, as `upf run --set`")
      ->allow_extra_args(false);

  bool info_markdown = false;
  auto* info = app.add_subcommand(
      "info", "list materials, solvers and world settings with their parameters");
  info->footer(R"(
Examples:
  upf info                 materials, solvers and world settings with units, defaults, ranges
  upf info --markdown      the same tables as the docs embed them)");
  info->add_flag("--markdown", info_markdown,
                 "print the parameter tables as the Markdown blocks of docs/ "
                 "(scripts/update-reference-docs copies them in)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::BadInput);
  }

  // Started by mpirun as several ranks: `upf run` splits the scene over them (with UPF_MPI);
  // anything else is refused before anything is written, and rank 0 says why.
  const upf::app::LaunchedRanks ranks = upf::app::launched_ranks();
#ifdef UPF_HAS_MPI
  std::optional<upf::app::MpiSession> mpi;
  if (*run && ranks.size > 1) {
    mpi.emplace(&argc, &argv);
    run_args.split_over_ranks = true;
    run_args.rank = mpi->rank();
  }
  // An error on one rank would leave the others waiting in their next exchange: on an error every
  // rank ends the job (MPI_Abort) with its exit code. Rank 0 reports the errors every rank meets
  // alike (bad input, an instability, which the ranks detect together); any other error is
  // reported by the rank that met it.
  auto fail = [&](int code, const std::string& message, bool collective) {
    if (!mpi) {
      std::cerr << message;
      return code;
    }
    if (mpi->rank() == 0 || !collective) std::cerr << message;
    std::cerr.flush();
    mpi->abort(code);
  };
#else
  auto fail = [](int code, const std::string& message, bool) {
    std::cerr << message;
    return code;
  };
#endif

  try {
    if (*compare || *render || (*run && !run_args.split_over_ranks)) {
      if (ranks.size > 1 && ranks.rank != 0) return static_cast<int>(upf::ExitCode::BadInput);
      upf::app::refuse_several_ranks(ranks, *run ? "run" : *compare ? "compare" : "render");
    }
    if (*run) {
      if (run_args.scene.empty() && run_args.resume.empty())
        throw upf::InputError("upf run", "give a scene file, or --resume DIR");
      return upf::app::run_command(run_args);
    }
    if (*compare) {
      compare_args.solvers_given = solvers->count() > 0;
      return upf::app::compare_command(compare_args);
    }
    if (*render) return upf::app::render_command(render_args);
    if (*view) return upf::viewer::run_viewer(view_options, upf::app::make_app_registry());
    if (*validate) return upf::app::validate_command(validate_files, validate_sets);
    if (*info) return upf::app::info_command(info_markdown);
  } catch (const upf::InputError& e) {
    return fail(static_cast<int>(ExitCode::BadInput),
                std::string("error: invalid input\n") + e.what() + '\n', true);
  } catch (const upf::InstabilityError& e) {
    return fail(
        static_cast<int>(ExitCode::Unstable),
        std::string("error: ") + e.what() + "\nthe last good frame was written; see summary.json\n",
        true);
  } catch (const std::exception& e) {
    return fail(static_cast<int>(ExitCode::Failure), std::string("error: ") + e.what() + '\n',
                false);
  }
  return 0;
}
