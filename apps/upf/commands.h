// The subcommands of `upf`.
#pragma once

#include <optional>

#include <string>
#include <vector>
#include "render_command.h"

namespace upf::app {

struct RunArgs {
  std::string scene;
  std::string out_dir;
  int threads = 0;
  bool fixed_threads = false;  // every thread even while the machine is busy
  std::optional<double> end_time;
  bool quiet = false;
  bool no_frames = false;
  // Write into a folder that holds files no upf run recorded (run_manifest.h): the files at the
  // names this run writes are replaced, nothing else is touched.
  bool overwrite = false;
  std::string solver;                 // empty: the scene's own solvers
  std::string checkpoint_every;       // empty: checkpoints only on Ctrl-C
  std::string resume;                 // a run directory to continue; then scene is empty
  std::vector<std::string> sets;      // --set POINTER=VALUE overrides (scene_overrides.h)
  std::optional<std::string> device;  // where the steps run; unset: the scene's "device"
  bool render = false;                // pictures of every frame once the run is done
  RenderArgs render_args;             // their look (the run directory is filled in)
  // Split over the MPI ranks that started it (mpirun -n P, P > 1): new domain cuts every
  // rebalance_every steps. Only rank 0 reports.
  bool split_over_ranks = false;
  int rank = 0;
  int rebalance_every = 10;
};

struct CompareArgs {
  std::string scene;
  std::vector<std::string> solvers;
  bool solvers_given = false;  // false: every registered solver the scene has particles for
  std::string out_dir = "out/compare";
  int threads = 0;
  bool fixed_threads = false;  // every thread even while the machine is busy
  std::optional<double> end_time;
  bool quiet = false;
  bool no_frames = false;
  std::string plot_script;        // empty: $UPF_PLOT_SCRIPT, else the source tree's script
  std::vector<std::string> sets;  // --set POINTER=VALUE overrides
  std::vector<std::string> vary;  // --vary POINTER=V1,V2,...: a sweep, every combination
  // A comparison split over processes (compare_plan_file.h): write OUT/plan.json only; run the
  // plan's run K; or report on the plan's finished runs.
  bool plan = false;
  std::optional<int> task;
  bool collect = false;
};

int run_command(const RunArgs& args);
int compare_command(const CompareArgs& args);
int validate_command(const std::vector<std::string>& files,
                     const std::vector<std::string>& sets = {});

}  // namespace upf::app
