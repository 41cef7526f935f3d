#include "solvers/fluid/equation_of_state_solver.h"

#include "framework/core/stopwatch.h"
#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"

namespace upf {

void EquationOfStateSolver::add_reactions(World& world, const FluidView& f, const Real* density,
                                          const Real* pressure) const {
  fluid_.add_reactions(world, f, density,
                       [&](std::uint32_t i) { return pressure[i] / (density[i] * density[i]); });
}

void EquationOfStateSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  prepare_method(world);
}

void EquationOfStateSolver::step(World& world, Real dt) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const FluidView f = fluid_.begin_step(world);
  Real* density = p.scalar_field("density").data();
  Real* pressure = p.scalar_field("pressure").data();

  Stopwatch watch;
  stats_ = SolverStats{};
  stats_.iterations = 1;

  fluid_.shared_forces(world, f, density);
  add_own_non_pressure(world, f, density);
  stats_.stage_ms.emplace_back("non_pressure", watch.lap_ms());

  compute_pressure(world, f, density, pressure);
  stats_.avg_density_error = average_compression(exec, fluid_.owned, f, density);
  stats_.max_density_error = max_compression(exec, fluid_.owned, f, density);
  stats_.stage_ms.emplace_back("pressure", watch.lap_ms());

  // Reactions on rigid bodies from this step's pressures and densities (Akinci 2012, eq. 11).
  add_reactions(world, f, density, pressure);
  fluid_.integrate(world, dt);
  stats_.stage_ms.emplace_back("integration", watch.lap_ms());
}

}  // namespace upf
