// Implicit Incompressible SPH (Ihmsen, Cornelis, Solenthaler, Horvath & Teschner 2014,
// "Implicit incompressible SPH", IEEE TVCG 20(3)), assembled from the shared fluid pieces
// (FluidSolverState) like every fluid solver.
//
// One step:
//   non_pressure  densities and kernel gradients at the current positions, gravity + viscosity
//                 + the grains' force (shared_forces), 1/D_i, the moving boundaries' part of the
//                 density's rate of change;
//   pressure      v_adv = v + dt a_other, rho_adv = rho + dt Drho/Dt(v_adv); pressures start at
//                 half the previous step's (the paper's warm start) and are relaxed by Jacobi
//                 iterations (omega = 0.5, the paper's) until the average compression of the
//                 predicted densities is at most eta, as PCISPH's stopping test; with
//                 summed_density_check, then checked against densities summed at x + dt v
//                 and iterated on while those exceed eta;
//   integration   reactions on bodies (boundary_reactions.h, P_i = p_i / rho_i^2), then
//                 symplectic Euler with the final pressure accelerations.
// The per-particle functions are in iisph_kernels.h.
#pragma once

#include <string>
#include <vector>

#include "framework/params/param_binding.h"
#include "framework/solver/solver.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "solvers/iisph/iisph_solve.h"

namespace upf {

struct IisphParams {
  double eta = 0;  // target average compression
  int min_iterations = 0, max_iterations = 0;
  double omega = 0;                 // Jacobi relaxation
  double stop_percentile = 0;       // StoppingError: 0 the average
  double wall_pressure = 0;         // boundary_pressure.h: 1 on, 0 Akinci's term alone
  double summed_density_check = 0;  // iisph_solve.h: 1 on
};

class IisphSolver final : public Solver {
 public:
  IisphSolver(const IisphParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override { return "iisph"; }
  void prepare(World& world) override;
  void initialize_fields(World& world) override { fluid_.initial_density(world); }
  Real max_time_step(const World& world) const override;
  std::vector<std::string> stages() const override;
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override { return fluid_.with_viscosity(stats_); }

  // What the device pipeline needs to run this solver's step (device/): the solve's settings
  // (iisph_solve.h), the stopping test and the shared fluid state.
  IisphSettings settings() const {
    return {params_.eta,   params_.min_iterations, params_.max_iterations,
            params_.omega, stopping_.is_average(), params_.summed_density_check != 0};
  }
  double stop_percentile() const { return stopping_.percentile(); }
  std::string cannot_split() const override { return stopping_.cannot_split(); }
  const FluidSolverState& fluid_state() const { return fluid_; }

  static ParamBinding<IisphParams> param_binding();

 private:
  IisphParams params_;
  std::vector<MaterialId> materials_;
  FluidSolverState fluid_;
  StoppingError stopping_;
  // Per-step fields, rewritten every step: fields, not buffers of the solver's own, because
  // neighbours read them, and ghosts on other ranks must carry them (particle_domain.h).
  FieldHandle<Real> inverse_diagonal_, boundary_divergence_, rho_adv_, predicted_, next_;
  FieldHandle<Vec3> v_adv_;
  FieldHandle<Vec3> x_star_;    // with summed_density_check only
  FieldHandle<Real> rho_star_;  // with summed_density_check only
  Real reference_speed_ = 0;    // sqrt(2 g H) of the initial liquid, for the CFL limit
  SolverStats stats_;
};

}  // namespace upf
