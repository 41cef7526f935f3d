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
};

// One run per name, in the order given. An empty list, an empty or repeated name, an unknown
// solver or one that would move nothing in the scene: all are reported at once, at `where`,
// as one InputError.
std::vector<SolverRunPlan> plan_comparison(const SceneDescription& scene, const Registry& registry,
                                           const std::vector<std::string>& solvers,
                                           const std::string& where = "--solvers");

}  // namespace upf
