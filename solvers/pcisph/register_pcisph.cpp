#include "solvers/pcisph/register_pcisph.h"

#include "framework/solver/registry.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "solvers/pcisph/pcisph_solver.h"

namespace upf {

void register_pcisph(Registry& registry) {
  registry.add_solver({
      "pcisph",
      ParticleType::Liquid,
      "Predictive-corrective incompressible SPH: iterates pressures until the average "
      "compression is below eta (the default fluid solver)",
      "Solenthaler & Pajarola 2009, Predictive-Corrective Incompressible SPH, ACM TOG 28(3)",
      PcisphSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<PcisphSolver>(PcisphSolver::param_binding().bind(values),
                                              std::move(materials));
      },
      fluid_solver_coupling(),
      /*density_contrast=*/true,
  });
}

}  // namespace upf
