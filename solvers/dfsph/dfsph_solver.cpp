#include "solvers/dfsph/dfsph_solver.h"

#include <algorithm>

#include "framework/world/world.h"
#include "solvers/dfsph/dfsph_kernels.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_time_step.h"

namespace upf {

namespace {
// The divergence-free solver leaves particles with fewer neighbours alone (SPlisHSPlasH's
// DFSPH does the same in 3D): near the free surface the rate of change of the density is that
// of a particle losing neighbours, not a compression.
constexpr std::uint32_t kMinDivergenceNeighbours = 20;
}  // namespace

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
  return b;
}

DfsphSolver::DfsphSolver(const DfsphParams& params, std::vector<MaterialId> materials)
    : params_(params), materials_(std::move(materials)), stopping_(params.stop_percentile) {}

void DfsphSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  Particles& p = world.particles();
  density_stiffness_ = p.declare_scalar("dfsph.density_stiffness");
  divergence_stiffness_ = p.declare_scalar("dfsph.divergence_stiffness");
  reference_speed_ = free_fall_speed(world);
}

Real DfsphSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, fluid_.max_viscosity, reference_speed_);
}

std::vector<std::string> DfsphSolver::stages() const {
  return {"non_pressure", "divergence", "pressure", "integration"};
}

std::pair<int, double> DfsphSolver::correct(World& world, const FluidView& f, const Real* density,
                                            Real dt, const Solve& solve) {
  const CpuExecutor& exec = world.executor();
  Particles& p = world.particles();
  const ParticleRange owned = fluid_.owned.range();
  Real* stiffness = p[solve.stiffness].data();
  const Real dt_power = solve.divergence ? dt : dt * dt;
  const DfsphVelocityStage update{f,
                                  fluid_.fluid_gradient.data(),
                                  fluid_.boundary_gradient.data(),
                                  k_.data(),
                                  dt,
                                  v_star_.data()};
  const DfsphStiffnessStage measure{f,
                                    fluid_.fluid_gradient.data(),
                                    fluid_.boundary_gradient.data(),
                                    boundary_divergence_.data(),
                                    density,
                                    factor_.data(),
                                    v_star_.data(),
                                    dt,
                                    Real(params_.omega),
                                    solve.divergence,
                                    kMinDivergenceNeighbours,
                                    rho_adv_.data(),
                                    k_.data()};
  const DfsphAccumulateStage accumulate{k_.data(), dt_power, k_total_.data(), stiffness};
  if (params_.warm_start) {
    exec.run(owned, measure);
    exec.run(owned, DfsphWarmStartStage{f, rho_adv_.data(), dt_power, stiffness, k_.data(),
                                        k_total_.data()});
    exec.run(owned, update);
  } else {
    exec.run(owned, ClearStiffnessStage{stiffness});
  }
  exec.run(owned, measure);
  // An exact stopping error (a fixed-point sum for the average): the same iteration count for
  // any thread count. The divergence-free solver bounds the average, as the paper does.
  auto stopping_error = [&] {
    return solve.divergence ? average_compression(exec, fluid_.owned, f, rho_adv_.data())
                            : stopping_(exec, fluid_.owned, f, rho_adv_.data());
  };
  double error = stopping_error();
  int iteration = 0;
  while (iteration < solve.max_iterations &&
         (iteration < solve.min_iterations || error > solve.eta)) {
    exec.run(owned, accumulate);
    exec.run(owned, update);
    exec.run(owned, measure);
    error = stopping_error();
    ++iteration;
  }
  return {iteration, error};
}

void DfsphSolver::step(World& world, Real dt, StageRunner& run) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const std::size_t n = p.size();
  FluidView f;
  Real* density = nullptr;
  stats_ = SolverStats{};

  run("non_pressure", [&] {
    f = fluid_.begin_step(world);
    density = p[fluid_.density_field].data();
    fluid_.shared_forces(world, f, density);
    factor_.resize(n);
    boundary_divergence_.resize(n);
    rho_adv_.resize(n);
    v_star_.resize(n);
    k_.assign(n, Real(0));
    k_total_.assign(n, Real(0));
    exec.run(fluid_.owned.range(),
             InverseDiagonalStage{f, fluid_.fluid_gradient.data(), fluid_.boundary_gradient.data(),
                                  factor_.data()});
    exec.run(fluid_.owned.range(), BoundaryVelocityDivergenceStage{f, boundary_divergence_.data()});
    exec.run(all_particles(n), CopyVelocityStage{p.velocity.data(), v_star_.data()});
  });

  run("divergence", [&] {
    divergence_iterations_ = 0;
    divergence_error_ = 0;
    if (!params_.divergence) return;
    const auto [iterations, error] =
        correct(world, f, density, dt,
                {true, params_.eta_divergence, 1, params_.max_divergence_iterations,
                 divergence_stiffness_});
    divergence_iterations_ = iterations;
    divergence_error_ = error;
  });

  run("pressure", [&] {
    exec.run(fluid_.owned.range(),
             VelocityKickStage{fluid_.other_acceleration.data(), dt, v_star_.data()});
    const auto [iterations, error] = correct(
        world, f, density, dt,
        {false, params_.eta, params_.min_iterations, params_.max_iterations, density_stiffness_});
    stats_.iterations = iterations;
    stats_.avg_density_error = stopping_.is_average()
                                   ? error
                                   : average_compression(exec, fluid_.owned, f, rho_adv_.data());
    stats_.max_density_error = max_compression(exec, fluid_.owned, f, rho_adv_.data());
  });

  run("integration", [&] {
    fluid_.add_reactions(world, f, density, TotalStiffness{k_total_.data()});
    exec.run(fluid_.owned.range(),
             DfsphIntegrateStage{v_star_.data(), k_total_.data(), density, dt, p.velocity.data(),
                                 p.position.data(), p[fluid_.pressure_field].data()});
  });
}

}  // namespace upf
