#include "solvers/dem/register_dem.h"

#include "framework/solver/registry.h"
#include "solvers/dem/dem_solver.h"
#include "solvers/dem/granular_blocks_section.h"

namespace upf {

void register_dem(Registry& registry) {
  registry.add_solver({
      "dem_linear",
      ParticleType::Granular,
      "Discrete elements with the linear spring-dashpot contact (damping from the restitution), "
      "a tangential spring with Coulomb's limit, rolling resistance and optional cohesion",
      "Cundall & Strack 1979, A discrete numerical model for granular assemblies, Geotechnique "
      "29(1)",
      DemSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<DemSolver>(
            DemModel::Linear, DemSolver::param_binding().bind(values), std::move(materials));
      },
      // Reactions on bodies and the drag and buoyancy's reaction on the liquid.
      {{CouplingArray::BoundaryForce, CouplingArray::LiquidForce}, {}, {}},
  });
  registry.add_solver({
      "dem_hertz",
      ParticleType::Granular,
      "Discrete elements with the Hertz-Mindlin contact (nonlinear normal force, Mindlin's "
      "tangential stiffness, damping from the restitution), Coulomb's limit, rolling resistance",
      "Tsuji, Tanaka & Ishida 1992, Lagrangian numerical simulation of plug flow of "
      "cohesionless particles in a horizontal pipe, Powder Technol. 71",
      DemSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<DemSolver>(DemModel::Hertz, DemSolver::param_binding().bind(values),
                                           std::move(materials));
      },
      // Reactions on bodies and the drag and buoyancy's reaction on the liquid.
      {{CouplingArray::BoundaryForce, CouplingArray::LiquidForce}, {}, {}},
  });
  registry.add_scene_section(granular_blocks_scene_section());
}

}  // namespace upf
