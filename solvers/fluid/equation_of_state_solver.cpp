#include "solvers/fluid/equation_of_state_solver.h"

#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"

namespace upf {

void EquationOfStateSolver::add_reactions(World& world, const FluidView& f, const Real* density,
                                          const Real* pressure) const {
  fluid_.add_reactions(world, f, density, PressureOverDensitySquared{pressure, density, Real(1)});
}

void EquationOfStateSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  prepare_method(world);
}

std::vector<std::string> EquationOfStateSolver::stages() const {
  return {"non_pressure", "pressure", "integration"};
}

void EquationOfStateSolver::step(World& world, Real dt, StageRunner& run) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  FluidView f;
  Real* density = nullptr;
  Real* pressure = nullptr;
  stats_ = SolverStats{};
  stats_.iterations = 1;

  run("non_pressure", [&] {
    f = fluid_.begin_step(world);
    density = p[fluid_.density_field].data();
    pressure = p[fluid_.pressure_field].data();
    fluid_.shared_forces(world, f, density, dt);
    add_own_non_pressure(world, f, density);
  });

  run("pressure", [&] {
    compute_pressure(world, f, density, pressure);
    stats_.avg_density_error = average_compression(exec, fluid_.owned, f, density);
    stats_.max_density_error = max_compression(exec, fluid_.owned, f, density);
  });

  // Reactions on rigid bodies from this step's pressures and densities (Akinci 2012, eq. 11).
  run("integration", [&] {
    add_reactions(world, f, density, pressure);
    fluid_.integrate(world, dt);
  });
}

}  // namespace upf
