#include "framework/compare/compare_plan.h"

#include <algorithm>
#include <cctype>

#include "framework/scene/solver_override.h"

namespace upf {

std::vector<SolverRunPlan> plan_comparison(const SceneDescription& scene, const Registry& registry,
                                           const std::vector<std::string>& solvers,
                                           const std::string& where) {
  std::vector<InputProblem> problems;
  std::vector<SolverRunPlan> plan;
  if (solvers.empty()) problems.push_back({where, "no solver given: name at least one"});
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const std::string& name = solvers[i];
    if (name.empty()) {
      problems.push_back({where, "empty solver name at position " + std::to_string(i + 1)});
      continue;
    }
    if (std::find(solvers.begin(), solvers.begin() + std::ptrdiff_t(i), name) !=
        solvers.begin() + std::ptrdiff_t(i)) {
      problems.push_back({where, "solver '" + name + "' is listed twice"});
      continue;
    }
    try {
      plan.push_back({name, with_solver(scene, registry, name, where)});
    } catch (const InputError& e) {
      problems.insert(problems.end(), e.problems().begin(), e.problems().end());
    }
  }
  if (!problems.empty()) throw InputError(std::move(problems));
  return plan;
}

SweepAxis parse_sweep_axis(const std::string& argument) {
  const std::string where = "--vary " + argument;
  const auto eq = argument.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(where,
                     "expected POINTER=V1,V2,... (a JSON pointer such as "
                     "/materials/water/solver/eta, then the values)");
  SweepAxis axis;
  axis.pointer = argument.substr(0, eq);
  if (axis.pointer.front() != '/')
    throw InputError(where, "the pointer must start with '/': " + axis.pointer);
  std::string values = argument.substr(eq + 1);
  std::size_t start = 0;
  while (true) {
    const auto comma = values.find(',', start);
    const std::string v = values.substr(start, comma == std::string::npos ? comma : comma - start);
    if (v.empty()) throw InputError(where, "an empty value in the list");
    axis.values.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  axis.key = axis.pointer.substr(axis.pointer.rfind('/') + 1);
  return axis;
}

std::vector<std::vector<std::string>> sweep_combinations(const std::vector<SweepAxis>& axes) {
  std::vector<std::vector<std::string>> combos{{}};
  for (const auto& axis : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& c : combos)
      for (const auto& v : axis.values) {
        next.push_back(c);
        next.back().push_back(axis.pointer + "=" + v);
      }
    combos = std::move(next);
  }
  return combos;
}

std::string sweep_run_name(const std::string& solver, const std::vector<SweepAxis>& axes,
                           const std::vector<std::string>& sets) {
  std::string name = solver;
  for (std::size_t a = 0; a < axes.size() && a < sets.size(); ++a) {
    std::string value = sets[a].substr(axes[a].pointer.size() + 1);
    for (char& c : value)
      if (c == '/' || c == '\\' || c == '"' || c == '\'' ||
          std::isspace(static_cast<unsigned char>(c)))
        c = '_';
    name += "," + axes[a].key + "=" + value;
  }
  return name;
}

}  // namespace upf
