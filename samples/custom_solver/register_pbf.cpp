#include "register_pbf.h"

#include "framework/solver/registry.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "pbf_solver.h"

namespace upf::pbf {

void register_pbf(Registry& registry) {
  registry.add_solver({
      "pbf",
      ParticleType::Liquid,
      "Position Based Fluids: a fixed number of Jacobi iterations on the density constraint per "
      "step, with artificial pressure, XSPH and vorticity confinement (a sample solver "
      "registered from samples/custom_solver)",
      "Macklin & Müller 2013, Position Based Fluids, ACM TOG 32(4)",
      PbfSolver::param_specs(),
      [](const ParamValues& values, std::vector<MaterialId> materials) {
        return std::make_unique<PbfSolver>(values, std::move(materials));
      },
      fluid_solver_coupling(),
  });
}

}  // namespace upf::pbf
