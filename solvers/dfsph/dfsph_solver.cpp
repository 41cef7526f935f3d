#include "solvers/dfsph/dfsph_solver.h"

#include <algorithm>

#include "framework/world/world.h"
#include "solvers/dfsph/dfsph_kernels.h"
#include "solvers/dfsph/dfsph_steps.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_time_step.h"

namespace upf {

ParamBinding<DfsphParams> DfsphSolver::param_binding() {
  ParamBinding<DfsphParams> b;
  b.add({"eta", "1", 0.01, 1e-6, 0.5,
         "constant-density solver: target compression (rho - rho0)/rho0 of the predicted "
         "densities; the loop ends once the stopping error (stop_percentile; by default the "
         "average) falls below it (PCISPH's eta)"},
        &DfsphParams::eta);
  b.add({"eta_divergence", "1", 0.01, 1e-6, 1,
         "divergence-free solver: target average density change per step, dt max(Drho/Dt, "
         "0)/rho0"},
        &DfsphParams::eta_divergence);
  b.add({"min_iterations", "1", 2, 1, 1000,
         "constant-density iterations always done (the paper: at least 2)"},
        &DfsphParams::min_iterations);
  b.add({"max_iterations", "1", 100, 1, 10000, "constant-density iterations at most"},
        &DfsphParams::max_iterations);
  b.add({"max_divergence_iterations", "1", 100, 1, 10000,
         "divergence-free iterations at most (at least 1 is done)"},
        &DfsphParams::max_divergence_iterations);
  b.add({"divergence", "1", 1, 0, 1,
         "1: run the divergence-free solver each step; 0: the constant-density solver only"},
        &DfsphParams::divergence);
  b.add({"omega", "1", 0.5, 0.05, 1,
         "relaxation of both solvers' Jacobi update (the paper: 1, which leaves water at rest "
         "jittering; 0.5 as IISPH's)"},
        &DfsphParams::omega);
  b.add({"warm_start", "1", 1, 0, 1,
         "1: each solver starts from the previous step's stiffness, as the paper does"},
        &DfsphParams::warm_start);
  b.add(stop_percentile_spec(), &DfsphParams::stop_percentile);
  b.add({"summed_density_check", "1", 0, 0, 1,
         "1: once the constant-density solve has converged on its linear prediction, sum the "
         "densities where the step leaves the particles (x + dt v*, as PCISPH predicts) and, while "
         "their stopping error exceeds eta, move the prediction halfway to them and iterate on "
         "(at most 4 rounds, a density sum each); with stop_percentile 100 the largest "
         "compression at the particles drops 2 to 3 times (docs/solvers.md)"},
        &DfsphParams::summed_density_check);
  b.add(wall_pressure_spec(), &DfsphParams::wall_pressure);
  return b;
}

DfsphSolver::DfsphSolver(const DfsphParams& params, std::vector<MaterialId> materials)
    : params_(params), materials_(std::move(materials)), stopping_(params.stop_percentile) {
  fluid_.wall_pressure = params.wall_pressure != 0;
}

void DfsphSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  Particles& p = world.particles();
  density_stiffness_ = p.declare_scalar(kDensityStiffness);
  divergence_stiffness_ = p.declare_scalar(kDivergenceStiffness);
  factor_ = p.declare_scratch_scalar(kDfsphFactorField);
  boundary_divergence_ = p.declare_scratch_scalar(kDfsphBoundaryDivergenceField);
  rho_adv_ = p.declare_scratch_scalar(kDfsphAdvectedDensityField);
  k_ = p.declare_scratch_scalar(kDfsphStiffnessField);
  k_total_ = p.declare_scratch_scalar(kDfsphTotalStiffnessField);
  v_star_ = p.declare_scratch_vector(kDfsphPredictedVelocityField);
  if (params_.summed_density_check) {
    x_star_ = p.declare_position_vector(kDfsphPredictedPositionField);
    rho_star_ = p.declare_scratch_scalar(kDfsphSummedDensityField);
    rho_base_ = p.declare_scratch_scalar(kDfsphBaseDensityField);
  }
  reference_speed_ = free_fall_speed(world);
}

Real DfsphSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, fluid_.force_limits(), reference_speed_);
}

std::vector<std::string> DfsphSolver::stages() const {
  return {"non_pressure", "divergence", "pressure", "integration"};
}

DfsphArrays DfsphSolver::arrays(World& world, const FluidView& f, const Real* density) {
  Particles& p = world.particles();
  DfsphArrays a{f,
                fluid_.owned.range(),
                p.size(),
                fluid_.fluid_gradient.data(),
                fluid_.boundary_gradient.data(),
                fluid_.other_acceleration.data(),
                density,
                p[density_stiffness_].data(),
                p[divergence_stiffness_].data(),
                p[factor_].data(),
                p[boundary_divergence_].data(),
                p[rho_adv_].data(),
                p[k_].data(),
                p[k_total_].data(),
                p[v_star_].data()};
  if (params_.summed_density_check) {
    a.x_star = p[x_star_].data();
    a.rho_star = p[rho_star_].data();
    a.rho_base = p[rho_base_].data();
  }
  return a;
}

DfsphSettings DfsphSolver::settings() const {
  return {params_.eta,
          params_.eta_divergence,
          params_.min_iterations,
          params_.max_iterations,
          params_.max_divergence_iterations,
          params_.divergence,
          params_.warm_start,
          params_.omega,
          stopping_.is_average(),
          params_.summed_density_check};
}

void DfsphSolver::step(World& world, Real dt, StageRunner& run) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  FluidView f;
  Real* density = nullptr;
  DfsphArrays a{};
  stats_ = SolverStats{};
  const DfsphSettings s = settings();
  auto stopping_error = [&](const CompressionValue& value) {
    return stopping_(exec, fluid_.owned, f, value.density);
  };

  run("non_pressure", [&] {
    f = fluid_.begin_step(world);
    density = p[fluid_.density_field].data();
    fluid_.shared_forces(world, f, density, dt);
    a = arrays(world, f, density);
    run_dfsph_non_pressure(exec, a);
  });

  run("divergence", [&] {
    divergence_iterations_ = 0;
    divergence_error_ = 0;
    if (!params_.divergence) return;
    const auto [iterations, error] = dfsph_correct(exec, a, s, dt, true, stopping_error);
    divergence_iterations_ = iterations;
    divergence_error_ = error;
  });

  run("pressure", [&] { stats_ = dfsph_pressure_solve(exec, a, s, dt, stopping_error); });

  run("integration", [&] {
    fluid_.add_reactions(world, f, density, TotalStiffness{p[k_total_].data()});
    run_dfsph_integration(exec, a, dt, p.velocity.data(), p.position.data(),
                          p[fluid_.pressure_field].data());
  });
}

}  // namespace upf
