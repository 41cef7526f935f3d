#include "solvers/iisph/iisph_solver.h"

#include <algorithm>
#include <utility>

#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/iisph/iisph_kernels.h"

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
  return b;
}

IisphSolver::IisphSolver(const IisphParams& params, std::vector<MaterialId> materials)
    : params_(params), materials_(std::move(materials)), stopping_(params.stop_percentile) {}

void IisphSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  reference_speed_ = free_fall_speed(world);
}

Real IisphSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, fluid_.max_viscosity, reference_speed_);
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
  stats_ = SolverStats{};

  run("non_pressure", [&] {
    f = fluid_.begin_step(world);
    density = p[fluid_.density_field].data();
    pressure = p[fluid_.pressure_field].data();
    fluid_.shared_forces(world, f, density);
    inverse_diagonal_.resize(n);
    boundary_divergence_.resize(n);
    rho_adv_.resize(n);
    predicted_.resize(n);
    v_adv_.resize(n);
    std::fill(fluid_.pressure_acceleration.begin(), fluid_.pressure_acceleration.end(), Vec3{});
    exec.run(fluid_.owned.range(),
             InverseDiagonalStage{f, fluid_.fluid_gradient.data(), fluid_.boundary_gradient.data(),
                                  inverse_diagonal_.data()});
    exec.run(fluid_.owned.range(), BoundaryVelocityDivergenceStage{f, boundary_divergence_.data()});
  });

  run("pressure", [&] {
    const ParticleRange owned = fluid_.owned.range();
    exec.run(all_particles(n), CopyVelocityStage{p.velocity.data(), v_adv_.data()});
    exec.run(owned, VelocityKickStage{fluid_.other_acceleration.data(), dt, v_adv_.data()});
    exec.run(owned, IisphAdvectedDensityStage{
                        f, fluid_.fluid_gradient.data(), fluid_.boundary_gradient.data(),
                        boundary_divergence_.data(), density, v_adv_.data(), dt, rho_adv_.data()});
    exec.run(owned, HalvePressureStage{pressure});
    next_.assign(pressure, pressure + n);  // particles not owned keep their pressure in both
    Real* current = pressure;
    Real* next = next_.data();
    Vec3* a_p = fluid_.pressure_acceleration.data();
    double error = 0;
    int iteration = 0;
    while (iteration < params_.max_iterations) {
      exec.run(owned, IisphPressureAccelerationStage{f, fluid_.fluid_gradient.data(),
                                                     fluid_.boundary_gradient.data(), density,
                                                     current, a_p});
      exec.run(owned, IisphPressureUpdateStage{
                          f, fluid_.fluid_gradient.data(), fluid_.boundary_gradient.data(), density,
                          inverse_diagonal_.data(), rho_adv_.data(), a_p, current, dt,
                          Real(params_.omega), predicted_.data(), next});
      // An exact stopping error (a fixed-point sum for the average): the same iteration count
      // for any thread count.
      error = stopping_(exec, fluid_.owned, f, predicted_.data());
      std::swap(current, next);
      ++iteration;
      if (iteration >= params_.min_iterations && error <= params_.eta) break;
    }
    if (current != pressure) exec.run(owned, CopyScalarStage{current, pressure});
    exec.run(owned, IisphPressureAccelerationStage{f, fluid_.fluid_gradient.data(),
                                                   fluid_.boundary_gradient.data(), density,
                                                   pressure, a_p});
    stats_.iterations = iteration;
    stats_.avg_density_error = stopping_.is_average()
                                   ? error
                                   : average_compression(exec, fluid_.owned, f, predicted_.data());
    stats_.max_density_error = max_compression(exec, fluid_.owned, f, predicted_.data());
  });

  run("integration", [&] {
    fluid_.add_reactions(world, f, density, PressureOverDensitySquared{pressure, density, 1});
    fluid_.integrate(world, dt);
  });
}

}  // namespace upf
