#include "solvers/sph/register_sph.h"

#include "framework/solver/registry.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "solvers/sph/sph_solver.h"

namespace upf {

void register_sph(Registry& registry) {
  registry.add_solver({
      "sph",
      ParticleType::Liquid,
      "Weakly compressible SPH with the state equation p = k (rho - rho0): one pressure "
      "evaluation per step, the step limited by the speed of sound sqrt(k)",
      "Müller, Charypar & Gross 2003, Particle-Based Fluid Simulation for Interactive "
      "Applications, SCA 2003",
      SphSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<SphSolver>(SphSolver::param_binding().bind(values),
                                           std::move(materials));
      },
      fluid_solver_coupling(),
  });
}

}  // namespace upf
