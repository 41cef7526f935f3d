#include "solvers/wcsph/register_wcsph.h"

#include "framework/solver/registry.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "solvers/wcsph/wcsph_solver.h"

namespace upf {

void register_wcsph(Registry& registry) {
  registry.add_solver({
      "wcsph",
      ParticleType::Liquid,
      "Weakly compressible SPH with the Tait equation: one pressure evaluation per step, the "
      "step limited by a speed of sound chosen for about 1 % density variation",
      "Becker & Teschner 2007, Weakly Compressible SPH for Free Surface Flows, SCA 2007",
      WcsphSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<WcsphSolver>(WcsphSolver::param_binding().bind(values),
                                             std::move(materials));
      },
      fluid_solver_coupling(),
      /*density_contrast=*/true,
  });
}

}  // namespace upf
