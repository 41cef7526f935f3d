#include "framework/compare/compare_plan.h"

#include <algorithm>

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

}  // namespace upf
