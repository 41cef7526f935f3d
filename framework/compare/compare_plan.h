// The runs of a comparison, checked before any of them starts: a bad solver list must not cost
// the time of the runs before the bad name.
#pragma once

#include <string>
#include <vector>

#include "framework/scene/scene.h"
#include "framework/solver/registry.h"

namespace upf {

struct SolverRunPlan {
  std::string solver;
  SceneDescription scene;  // the scene with `solver` moving its particle type (with_solver)
  // The run's name: its row's label and its directory under OUT/. The solver's name, or in a
  // sweep the solver's with the swept values, "pcisph,eta=0.002".
  std::string name = solver;
};

// One run per name, in the order given. An empty list, an empty or repeated name, an unknown
// solver or one that would move nothing in the scene: all are reported at once, at `where`,
// as one InputError.
std::vector<SolverRunPlan> plan_comparison(const SceneDescription& scene, const Registry& registry,
                                           const std::vector<std::string>& solvers,
                                           const std::string& where = "--solvers");

// A swept value: `--vary POINTER=V1,V2,...` set to one of its values, as `--set POINTER=V`.
struct SweepAxis {
  std::string pointer;              // "/materials/water/solver/eta"
  std::vector<std::string> values;  // as written: "0.01", "0.005"
  std::string key;                  // in run names: the pointer's last token ("eta")
  std::string option;               // "--vary ARG" as given, for messages
};

// "POINTER=V1,V2,...": InputError naming `--vary ARG` without '=', a value or a pointer, and for
// two values that set the same value ("1", "1.0") or become the same in run names ("a/b", "a_b").
SweepAxis parse_sweep_axis(const std::string& argument);

// InputError naming both options when two axes set the same pointer, or a later one a value
// that holds an earlier one's (/a after /a/b): the later would overwrite the earlier's values
// while the runs stay named after them.
void check_sweep_axes(const std::vector<SweepAxis>& axes);

// Every combination of the axes' values, as --set arguments ("/a=1"), the first axis slowest;
// one empty combination without axes.
std::vector<std::vector<std::string>> sweep_combinations(const std::vector<SweepAxis>& axes);

// A value as run names show it: characters a directory name should not hold ('/', '\\',
// whitespace, quotes) become '_'.
std::string sweep_value_label(std::string value);

// A run's name: the solver's, then ",key=label" per axis.
std::string sweep_run_name(const std::string& solver, const std::vector<SweepAxis>& axes,
                           const std::vector<std::string>& sets);

// Each name becomes a folder under OUT/: InputError at `where` for a name that is not one plain
// file name (file_name.h), or the same as another's.
void check_run_names(const std::vector<std::string>& names, const std::string& where);

}  // namespace upf
