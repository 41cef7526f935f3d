#include "framework/scene/solver_override.h"

#include "framework/scene/json_input.h"
#include "framework/scene/liquid_mix_keys.h"

namespace upf {

namespace {

bool has_material_of_type(const SceneDescription& scene, ParticleType type) {
  for (const auto& m : scene.materials)
    if (m.type == type) return true;
  return false;
}

std::string unknown_solver_message(const std::string& name, const Registry& registry) {
  std::vector<std::string> names;
  std::string list;
  for (const auto& s : registry.solvers()) {
    names.push_back(s.name);
    list += (list.empty() ? "" : ", ") + s.name;
  }
  std::string msg = "unknown solver '" + name + "'";
  if (auto guess = did_you_mean(name, names)) msg += " (did you mean '" + *guess + "'?)";
  return msg + "; registered solvers: " + (list.empty() ? "none" : list);
}

// Two liquids of different rest density: only solvers with the density-contrast forms hold them.
bool can_move(const SolverInfo& s, const SceneDescription& scene) {
  if (!has_material_of_type(scene, s.type)) return false;
  return s.type != ParticleType::Liquid || s.density_contrast || !liquids_differ_in_density(scene);
}

}  // namespace

SceneDescription with_solver(const SceneDescription& scene, const Registry& registry,
                             const std::string& solver, const std::string& where) {
  const SolverInfo* info = registry.find_solver(solver);
  if (!info) throw InputError(where, unknown_solver_message(solver, registry));
  if (!has_material_of_type(scene, info->type)) {
    const std::string type(to_string(info->type));
    throw InputError(where, "solver '" + solver + "' moves " + type + " particles, but scene '" +
                                scene.name + "' has no " + type + " material");
  }
  if (!can_move(*info, scene))
    throw InputError(where, "solver '" + solver +
                                "' sums densities over neighbours' masses and "
                                "cannot hold the liquids of scene '" +
                                scene.name + "', whose rest densities differ (docs/multiphase.md)");
  // Materials sharing a solver share one instance and so one parameter set: the scene's, when
  // one of its materials already names this solver.
  ParamValues params(info->params);
  for (const auto& m : scene.materials)
    if (m.solver == solver) {
      params = m.solver_params;
      break;
    }
  SceneDescription out = scene;
  for (auto& m : out.materials) {
    if (m.type != info->type) continue;
    m.solver = solver;
    m.solver_params = params;
  }
  return out;
}

std::vector<std::string> solvers_for_scene(const SceneDescription& scene,
                                           const Registry& registry) {
  std::vector<std::string> names;
  for (const auto& s : registry.solvers())
    if (can_move(s, scene)) names.push_back(s.name);
  return names;
}

}  // namespace upf
