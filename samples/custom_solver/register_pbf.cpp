#include "register_pbf.h"

#include "framework/solver/registry.h"
#include "pbf_solver.h"
#include "solvers/fluid/fluid_solver_state.h"

namespace upf::pbf {

void register_pbf(Registry& registry) {
  registry.add_solver({
      "pbf",
      ParticleType::Liquid,
      "Position Based Fluids: a fixed number of Jacobi iterations on the density constraint per "
      "step, with artificial pressure, XSPH and vorticity confinement (a sample solver "
      "registered from samples/custom_solver)",
      "Macklin & Müller 2013, Position Based Fluids, ACM TOG 32(4)",
      PbfSolver::param_binding().specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<PbfSolver>(PbfSolver::param_binding().bind(values),
                                           std::move(materials));
      },
      fluid_solver_coupling(),
  });
}

}  // namespace upf::pbf
