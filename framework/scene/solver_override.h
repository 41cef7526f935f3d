// One solver for a whole scene: `upf run --solver NAME` and each run of `upf compare`. The named
// solver moves every material whose particle type it handles (liquids for fluid solvers); the
// rest of the scene (particles, probes, time) is unchanged, so runs differ only by the solver.
#pragma once

#include <string>
#include <vector>

#include "framework/scene/scene.h"
#include "framework/solver/registry.h"

namespace upf {

// The scene with `solver` moving every material of its particle type. Parameters the scene gives
// that solver are kept (a material already naming it sets them for all); otherwise the solver's
// defaults apply. Throws InputError at `where` for an unknown solver (listing the registered ones,
// with a did-you-mean), one whose particle type no material of the scene has, or a liquid solver
// without the density-contrast forms for liquids of different rest density.
SceneDescription with_solver(const SceneDescription& scene, const Registry& registry,
                             const std::string& solver, const std::string& where = "--solver");

// Registered solvers, in registry order, that with_solver accepts for the scene.
std::vector<std::string> solvers_for_scene(const SceneDescription& scene, const Registry& registry);

}  // namespace upf
