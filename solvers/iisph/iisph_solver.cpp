#include "solvers/iisph/iisph_solver.h"

#include <algorithm>
#include <utility>

#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/iisph/iisph_solve.h"

namespace upf {

ParamBinding<IisphParams> IisphSolver::param_binding() {
  ParamBinding<IisphParams> b;
  b.add({"eta", "1", 0.01, 1e-6, 0.5,
         "target compression (rho - rho0)/rho0 of the predicted densities: the Jacobi "
         "iterations end once the stopping error (stop_percentile; by default the average) "
         "falls below it (PCISPH's eta)"},
        &IisphParams::eta);
  b.add(
      {"min_iterations", "1", 2, 1, 1000, "Jacobi iterations always done (the paper: at least 2)"},
      &IisphParams::min_iterations);
  b.add({"max_iterations", "1", 100, 1, 10000, "Jacobi iterations at most"},
        &IisphParams::max_iterations);
  b.add({"omega", "1", 0.5, 0.05, 1, "relaxation of the Jacobi update (the paper: 0.5)"},
        &IisphParams::omega);
  b.add(stop_percentile_spec(), &IisphParams::stop_percentile);
  b.add(wall_pressure_spec(), &IisphParams::wall_pressure);
  b.add({"summed_density_check", "1", 0, 0, 1,
         "1: once the Jacobi iterations have converged on their linear prediction, sum the "
         "densities where the step leaves the particles (x + dt v, as PCISPH predicts) and, while "
         "their stopping error exceeds eta, move the prediction halfway to them and iterate on "
         "(at most 4 rounds, a density sum each); with stop_percentile 100 the largest "
         "compression at the particles drops 2 to 3 times (docs/solvers.md)"},
        &IisphParams::summed_density_check);
  return b;
}

IisphSolver::IisphSolver(const IisphParams& params, std::vector<MaterialId> materials)
    : params_(params), materials_(std::move(materials)), stopping_(params.stop_percentile) {
  fluid_.wall_pressure = params.wall_pressure != 0;
}

void IisphSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  Particles& p = world.particles();
  inverse_diagonal_ = p.declare_scratch_scalar(kIisphInverseDiagonalField);
  boundary_divergence_ = p.declare_scratch_scalar(kIisphBoundaryDivergenceField);
  rho_adv_ = p.declare_scratch_scalar(kIisphAdvectedDensityField);
  predicted_ = p.declare_scratch_scalar(kIisphPredictedDensityField);
  next_ = p.declare_scratch_scalar(kIisphNextPressureField);
  v_adv_ = p.declare_scratch_vector(kIisphAdvectedVelocityField);
  if (params_.summed_density_check != 0) {
    x_star_ = p.declare_position_vector(kIisphPredictedPositionField);
    rho_star_ = p.declare_scratch_scalar(kIisphSummedDensityField);
  }
  reference_speed_ = free_fall_speed(world);
}

Real IisphSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, fluid_.force_limits(), reference_speed_);
}

std::vector<std::string> IisphSolver::stages() const {
  return {"non_pressure", "pressure", "integration"};
}

void IisphSolver::step(World& world, Real dt, StageRunner& run) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const std::size_t n = p.size();
  FluidView f;
  Real* density = nullptr;
  Real* pressure = nullptr;
  IisphArrays arrays{};
  stats_ = SolverStats{};

  run("non_pressure", [&] {
    f = fluid_.begin_step(world);
    density = p[fluid_.density_field].data();
    pressure = p[fluid_.pressure_field].data();
    fluid_.shared_forces(world, f, density, dt);
    arrays = {f,
              fluid_.owned.range(),
              n,
              fluid_.fluid_gradient.data(),
              fluid_.boundary_gradient.data(),
              fluid_.other_acceleration.data(),
              density,
              fluid_.pressure_acceleration,
              pressure,
              p[inverse_diagonal_].data(),
              p[boundary_divergence_].data(),
              p[rho_adv_].data(),
              p[predicted_].data(),
              p[next_].data(),
              p[v_adv_].data()};
    if (params_.summed_density_check != 0) {
      arrays.x_star = p[x_star_].data();
      arrays.rho_star = p[rho_star_].data();
    }
    run_iisph_non_pressure(exec, arrays);
  });

  run("pressure", [&] {
    stats_ = iisph_pressure_solve(exec, arrays, settings(), dt, [&](const CompressionValue& value) {
      return stopping_(exec, fluid_.owned, f, value.density);
    });
  });

  run("integration", [&] {
    fluid_.add_reactions(world, f, density, PressureOverDensitySquared{pressure, density, 1});
    fluid_.integrate(world, dt);
  });
}

}  // namespace upf
