// Which particle fields a run writes into its frames.
#pragma once

#include <string>
#include <vector>

#include "framework/particles/particles.h"
#include "framework/scene/scene.h"

namespace upf {

// The fields the scene names in output.fields, or every exported field when it names none. Only
// the solvers know which fields exist, so this runs after World::prepare(); a name that no solver
// exports is an InputError under its JSON path, with a did-you-mean and the names there are
// (exported fields only: they are the ones kept in the last good state after an instability).
std::vector<std::string> check_output_fields(const SceneDescription& scene,
                                             const Particles& particles);

}  // namespace upf
