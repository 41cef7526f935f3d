// Scene checks for several liquids in one scene: who moves them and how far their rest densities
// may differ (solvers/fluid/density_contrast.h, docs/multiphase.md).
#pragma once

#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/solver/registry.h"

namespace upf {

// The largest ratio of two liquids' rest densities: the interface method (Solenthaler &
// Pajarola 2008) is the paper's up to 10, and so are upf's tests.
inline constexpr double kMaxLiquidDensityRatio = 10;

// Whether two of the scene's liquid materials differ in rest density.
bool liquids_differ_in_density(const SceneDescription& scene);

// A problem for each of: two liquids naming different solvers (each pressure solve moves its own
// particles and would treat the other's as unpressured mass), liquids of different rest density
// under a solver without the density-contrast forms (SolverInfo::density_contrast), and a density
// ratio above kMaxLiquidDensityRatio. Each names both materials.
void check_liquid_mix_keys(JsonInput& in, const Registry& registry, const SceneDescription& scene);

}  // namespace upf
