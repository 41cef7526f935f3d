#include "solvers/dfsph/register_dfsph.h"

#include "framework/solver/registry.h"
#include "solvers/dfsph/dfsph_solver.h"
#include "solvers/fluid/fluid_solver_state.h"

namespace upf {

void register_dfsph(Registry& registry) {
  registry.add_solver({
      "dfsph",
      ParticleType::Liquid,
      "Divergence-free SPH: a divergence-free solver on the velocities, then a constant-density "
      "solver, both warm-started, until the average errors are below eta_divergence and eta",
      "Bender & Koschier 2015, Divergence-free smoothed particle hydrodynamics, SCA; 2017, IEEE "
      "TVCG 23(3)",
      DfsphSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<DfsphSolver>(DfsphSolver::param_binding().bind(values),
                                             std::move(materials));
      },
      fluid_solver_coupling(),
      /*density_contrast=*/true,
  });
}

}  // namespace upf
