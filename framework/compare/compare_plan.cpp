#include "framework/compare/compare_plan.h"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "framework/core/file_name.h"
#include "framework/scene/solver_override.h"

namespace upf {

namespace {
// A value as `--set` reads it (scene_overrides.h): JSON, else the text as a string. So "1" and
// "1.0" are the same value, and would be the same run twice.
nlohmann::json set_value(const std::string& text) {
  nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
  if (value.is_discarded()) value = text;
  return value;
}
}  // namespace

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
    // The name is the run's folder under OUT/ (a Python solver may be registered as "../x").
    if (auto bad = file_name_problem(name)) {
      problems.push_back(
          {where, "solver '" + name + "' " + *bad + ": a run's folder is named after its solver"});
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
  axis.option = where;
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
  // Each value is a run and a folder of its own: two that set the same value would run twice,
  // and two with the same label would share a folder, the second run overwriting the first.
  std::vector<InputProblem> problems;
  for (std::size_t i = 0; i < axis.values.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const std::string &a = axis.values[j], &b = axis.values[i];
      if (set_value(a) == set_value(b)) {
        problems.push_back({where, a == b ? "the value '" + a + "' is given twice"
                                          : "the values '" + a + "' and '" + b +
                                                "' set the same value: give it once"});
        break;
      }
      if (sweep_value_label(a) == sweep_value_label(b)) {
        problems.push_back({where, "the values '" + a + "' and '" + b + "' both become '" +
                                       sweep_value_label(a) +
                                       "' in the runs' names, and so share their folders ('/', "
                                       "'\\', spaces and quotes become '_'): give values that "
                                       "differ otherwise"});
        break;
      }
    }
  if (!problems.empty()) throw InputError(std::move(problems));
  return axis;
}

void check_sweep_axes(const std::vector<SweepAxis>& axes) {
  std::vector<InputProblem> problems;
  for (std::size_t i = 0; i < axes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const std::string &earlier = axes[j].pointer, &later = axes[i].pointer;
      const std::string both = axes[j].option + " and " + axes[i].option;
      if (earlier == later)
        problems.push_back({both, "both set " + later +
                                      ": the later would overwrite the earlier's values while the "
                                      "runs are named after both; give the pointer once, with "
                                      "all its values"});
      else if (earlier.rfind(later + "/", 0) == 0)
        problems.push_back({both, "the later replaces " + later + ", which holds " + earlier +
                                      ", so the earlier's values would be lost: give " + later +
                                      " first, or vary one of them"});
    }
  if (!problems.empty()) throw InputError(std::move(problems));
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

std::string sweep_value_label(std::string value) {
  for (char& c : value)
    if (c == '/' || c == '\\' || c == '"' || c == '\'' ||
        std::isspace(static_cast<unsigned char>(c)))
      c = '_';
  return value;
}

std::string sweep_run_name(const std::string& solver, const std::vector<SweepAxis>& axes,
                           const std::vector<std::string>& sets) {
  std::string name = solver;
  for (std::size_t a = 0; a < axes.size() && a < sets.size(); ++a)
    name += "," + axes[a].key + "=" + sweep_value_label(sets[a].substr(axes[a].pointer.size() + 1));
  return name;
}

void check_run_names(const std::vector<std::string>& names, const std::string& where) {
  std::vector<InputProblem> problems;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (auto bad = file_name_problem(names[i])) {
      problems.push_back({where, "the run name '" + names[i] + "' " + *bad +
                                     ": it becomes the run's folder under the output folder"});
      continue;
    }
    if (std::find(names.begin(), names.begin() + std::ptrdiff_t(i), names[i]) !=
        names.begin() + std::ptrdiff_t(i))
      problems.push_back(
          {where, "two runs are named '" + names[i] + "': they would share a folder"});
  }
  if (!problems.empty()) throw InputError(std::move(problems));
}

}  // namespace upf
