#include "solvers/iisph/register_iisph.h"

#include "framework/solver/registry.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "solvers/iisph/iisph_solver.h"

namespace upf {

void register_iisph(Registry& registry) {
  registry.add_solver({
      "iisph",
      ParticleType::Liquid,
      "Implicit incompressible SPH: relaxed Jacobi iterations on the pressure Poisson equation, "
      "warm-started, until the average compression is below eta",
      "Ihmsen, Cornelis, Solenthaler, Horvath & Teschner 2014, Implicit incompressible SPH, IEEE "
      "TVCG 20(3)",
      IisphSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<IisphSolver>(IisphSolver::param_binding().bind(values),
                                             std::move(materials));
      },
      fluid_solver_coupling(),
      /*density_contrast=*/true,
  });
}

}  // namespace upf
