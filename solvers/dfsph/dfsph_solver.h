// Divergence-Free SPH (Bender & Koschier 2015, "Divergence-free smoothed particle
// hydrodynamics", SCA; 2017, "Divergence-free SPH for incompressible and viscous fluids", IEEE
// TVCG 23(3)), assembled from the shared fluid pieces (FluidSolverState) like every fluid solver.
//
// One step (the paper's Algorithm 1, with the world's neighbour search at its start):
//   non_pressure  densities and kernel gradients at the current positions, the factors 1/D_i,
//                 gravity + viscosity + the grains' force (shared_forces);
//   divergence    the divergence-free solver: corrects v until the average density change per
//                 step, dt max(Drho/Dt, 0) / rho0, is below eta_divergence (warm-started);
//   pressure      v* = v + dt a_other, then the constant-density solver corrects v* until the
//                 average predicted compression is below eta (warm-started), as PCISPH's eta;
//   integration   reactions on bodies from the step's total K (boundary_reactions.h), v = v*,
//                 x += dt v.
// The per-particle functions are in dfsph_kernels.h. The viscosity is evaluated before the
// divergence solve (the paper evaluates it after the previous step's): the shared forces are
// computed together with the density the factors need.
//
// Relaxation: both solvers update every particle at once from its neighbours' previous K (a
// Jacobi iteration), which overshoots modes that alternate from particle to particle. With the
// paper's full step (omega = 1) water at rest in samples/hydrostatic_tank.json kept jittering
// (kinetic energy 0.025-0.03 J after 1.5 s, PCISPH 0.003 J) and more iterations made it worse
// (0.05 J with 4 per step); omega = 0.5, IISPH's relaxation, settles it to 0.003 J and more
// iterations then reduce the error. docs/solvers.md has the figures.
//
// Warm starts: each solver starts from the K of the previous step (stored without its dt, in the
// fields dfsph.density_stiffness and dfsph.divergence_stiffness so they follow reordering), as
// the paper does; `warm_start` 0 switches it off.
#pragma once

#include <string>
#include <vector>

#include "framework/params/param_binding.h"
#include "framework/solver/solver.h"
#include "solvers/dfsph/dfsph_steps.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_solver_state.h"

namespace upf {

struct DfsphParams {
  double eta = 0;             // constant-density solver: target average compression
  double eta_divergence = 0;  // divergence-free solver: target average density change per step
  int min_iterations = 0, max_iterations = 0;
  int max_divergence_iterations = 0;
  bool divergence = true;  // run the divergence-free solver
  bool warm_start = true;
  double omega = 0;                   // relaxation of the Jacobi update
  double stop_percentile = 0;         // the constant-density solver's StoppingError: 0 the average
  double wall_pressure = 0;           // boundary_pressure.h: 1 on, 0 Akinci's term alone
  bool summed_density_check = false;  // dfsph_summed_density.h
};

class DfsphSolver final : public Solver {
 public:
  DfsphSolver(const DfsphParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override { return "dfsph"; }
  void prepare(World& world) override;
  void initialize_fields(World& world) override { fluid_.initial_density(world); }
  Real max_time_step(const World& world) const override;
  std::vector<std::string> stages() const override;
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override { return fluid_.with_viscosity(stats_); }

  static ParamBinding<DfsphParams> param_binding();
  // The warm starts' fields: K / dt^2 and K / dt of the last step.
  static constexpr const char* kDensityStiffness = "dfsph.density_stiffness";
  static constexpr const char* kDivergenceStiffness = "dfsph.divergence_stiffness";
  // The solves' settings, for the device pipeline too.
  DfsphSettings settings() const;
  const FluidSolverState& fluid_state() const { return fluid_; }
  double stop_percentile() const { return stopping_.percentile(); }
  std::string cannot_split() const override { return stopping_.cannot_split(); }
  // The divergence-free solver's last step: iterations and average density change per step.
  int divergence_iterations() const { return divergence_iterations_; }
  double divergence_error() const { return divergence_error_; }

 private:
  // The shared step's views (dfsph_steps.h) of this step's arrays.
  DfsphArrays arrays(World& world, const FluidView& f, const Real* density);
  DfsphParams params_;
  std::vector<MaterialId> materials_;
  FluidSolverState fluid_;
  StoppingError stopping_;
  FieldHandle<Real> density_stiffness_, divergence_stiffness_;
  // Per-step fields, rewritten every step: fields, not buffers of the solver's own, because
  // neighbours read them, and ghosts on other ranks must carry them (particle_domain.h).
  FieldHandle<Real> factor_, boundary_divergence_, rho_adv_, k_, k_total_;
  FieldHandle<Vec3> v_star_;
  FieldHandle<Vec3> x_star_;               // with summed_density_check only
  FieldHandle<Real> rho_star_, rho_base_;  // likewise
  Real reference_speed_ = 0;               // sqrt(2 g H) of the initial liquid, for the CFL limit
  SolverStats stats_;
  int divergence_iterations_ = 0;
  double divergence_error_ = 0;
};

}  // namespace upf
