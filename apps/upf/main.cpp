// upf: the command-line program. Thin: it parses arguments and calls the framework.
//   upf run SCENE [--out DIR] [--threads N] [--end T] [--quiet]
//   upf validate SCENE...
//   upf info
// Exit codes: 0 ok, 1 other failure (output), 2 bad input, 3 unstable run.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "framework/core/errors.h"

int main(int argc, char** argv) {
  using upf::ExitCode;
  CLI::App app{
      "upf: unified particle framework (liquids, rigid bodies, granular media, frozen "
      "boundaries in one particle world)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "upf 0.1.0");

  upf::app::RunArgs run_args;
  auto* run = app.add_subcommand("run", "run a scene: frames, metrics and probes into --out");
  run->add_option("scene", run_args.scene, "scene file (JSON)")->required();
  run->add_option("--out,-o", run_args.out_dir, "output directory (default out/<scene name>)");
  run->add_option("--threads,-j", run_args.threads, "CPU threads (default: all)")
      ->check(CLI::Range(1, 1024));
  run->add_option("--end", run_args.end_time, "end time in seconds, overriding the scene's")
      ->check(CLI::PositiveNumber);
  run->add_flag("--quiet,-q", run_args.quiet, "no progress output");
  run->add_flag("--no-frames", run_args.no_frames, "write metrics and probes only");

  std::vector<std::string> validate_files;
  auto* validate = app.add_subcommand("validate", "check scene files; list every problem");
  validate->add_option("scenes", validate_files, "scene files")->required();

  auto* info = app.add_subcommand("info", "list solvers and materials with their parameters");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::BadInput);
  }

  try {
    if (*run) return upf::app::run_command(run_args);
    if (*validate) return upf::app::validate_command(validate_files);
    if (*info) return upf::app::info_command();
  } catch (const upf::InputError& e) {
    std::cerr << "error: invalid input\n" << e.what() << '\n';
    return static_cast<int>(ExitCode::BadInput);
  } catch (const upf::InstabilityError& e) {
    std::cerr << "error: " << e.what() << "\nthe last good frame was written; see summary.json\n";
    return static_cast<int>(ExitCode::Unstable);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return static_cast<int>(ExitCode::Failure);
  }
  return 0;
}
