// The common step of fluid solvers whose pressure follows from the density through a state
// equation, evaluated once per step (SolverStats::iterations = 1): SPH (Müller et al. 2003) and
// WCSPH (Becker & Teschner 2007). The stages, timed as PCISPH's:
//   non_pressure   shared density, gradients and forces (FluidSolverState::shared_forces), then
//                  the method's own additions (add_own_non_pressure);
//   pressure       pressures and pressure accelerations (compute_pressure), then the density
//                  error statistics every fluid solver reports (compression_stats.h);
//   integration    symplectic Euler.
#pragma once

#include <vector>

#include "framework/solver/solver.h"
#include "solvers/fluid/fluid_solver_state.h"

namespace upf {

class EquationOfStateSolver : public Solver {
 public:
  explicit EquationOfStateSolver(std::vector<MaterialId> materials)
      : materials_(std::move(materials)) {}

  void prepare(World& world) final;
  void initialize_fields(World& world) override { fluid_.initial_density(world); }
  std::vector<std::string> stages() const final;
  void step(World& world, Real dt, StageRunner& run) final;
  SolverStats stats() const final { return fluid_.with_viscosity(stats_); }
  // The shared fluid state, for the device pipeline (device/).
  const FluidSolverState& fluid_state() const { return fluid_; }

 protected:
  // boundary_pressure.h; off unless the solver turns it on.
  void set_wall_pressure(bool on) { fluid_.wall_pressure = on; }
  // Called by prepare() once the shared state is set up.
  virtual void prepare_method(World& world) = 0;
  // After the shared forces: the method's own density (written over `density`, which holds the
  // shared cubic spline density) and viscosity (added to fluid().other_acceleration).
  virtual void add_own_non_pressure(const World& world, const FluidView& f, Real* density) = 0;
  // Writes `pressure` and fluid().pressure_acceleration for the owned particles.
  virtual void compute_pressure(const World& world, const FluidView& f, const Real* density,
                                Real* pressure) = 0;

  // Reactions on rigid boundary particles (boundary_reactions.h). The default is the pair term
  // p_i / rho_i^2 with the cubic spline; a solver whose boundary term differs overrides it.
  virtual void add_reactions(World& world, const FluidView& f, const Real* density,
                             const Real* pressure) const;

  const std::vector<MaterialId>& materials() const { return materials_; }
  FluidSolverState& fluid() { return fluid_; }
  const FluidSolverState& fluid() const { return fluid_; }

 private:
  std::vector<MaterialId> materials_;
  FluidSolverState fluid_;
  SolverStats stats_;
};

}  // namespace upf
