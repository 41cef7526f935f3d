#include "solvers/pcisph/pcisph_solver.h"

#include <algorithm>
#include <cmath>

#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/fluid/lattice_template.h"
#include "solvers/pcisph/pcisph_correction_loop.h"
#include "solvers/pcisph/pcisph_kernels.h"

namespace upf {

ParamBinding<PcisphParams> PcisphSolver::param_binding() {
  ParamBinding<PcisphParams> b;
  b.add({"eta", "1", 0.01, 1e-6, 0.5,
         "target compression (rho - rho0)/rho0: the correction loop ends once the stopping "
         "error (stop_percentile; by default the average compression) falls below it"},
        &PcisphParams::eta);
  b.add({"min_iterations", "1", 3, 1, 1000, "correction iterations always done"},
        &PcisphParams::min_iterations);
  b.add({"max_iterations", "1", 100, 1, 10000,
         "correction iterations at most; not checked against min_iterations: if min_iterations "
         "> max_iterations, the loop stops at max_iterations"},
        &PcisphParams::max_iterations);
  b.add({"divergence_factor", "1", 1.2, 0, 1000,
         "past min_iterations, the loop also ends when the stopping error exceeds this times its "
         "smallest value in the step (an iteration that pumps pressure at an impact instead of "
         "converging); 0: never"},
        &PcisphParams::divergence_factor);
  b.add(stop_percentile_spec(), &PcisphParams::stop_percentile);
  b.add(wall_pressure_spec(), &PcisphParams::wall_pressure);
  b.add({"rest_compression", "1", 0.7, 0, 1,
         "the time step keeps liquid at rest compressed by at most this share of eta (it grows "
         "as 0.16 g H (dt/s)^2); above about 0.8 the pressure at walls and on bodies flickers "
         "from step to step; 0: no such limit"},
        &PcisphParams::rest_compression);
  return b;
}

PcisphSolver::PcisphSolver(const PcisphParams& params, std::vector<MaterialId> materials)
    : eta_(params.eta),
      rest_compression_(params.rest_compression),
      stopping_(params.stop_percentile),
      min_iterations_(params.min_iterations),
      max_iterations_(params.max_iterations),
      divergence_factor_(params.divergence_factor),
      materials_(std::move(materials)) {
  fluid_.wall_pressure = params.wall_pressure != 0;
}

double PcisphSolver::template_delta_scale(Real spacing, const CubicSplineKernel& kernel) {
  // A particle with a full neighbourhood on the initial cubic lattice.
  Vec3 sum_grad{};
  double sum_grad2 = 0;
  for_each_lattice_offset(spacing, kernel.support_radius(), [&](const Vec3& r) {
    const Vec3 g = kernel.gradient(r);
    sum_grad += g;
    sum_grad2 += double(squared_norm(g));
  });
  const double denominator = double(squared_norm(sum_grad)) + sum_grad2;
  // m / rho0 = spacing^3 for lattice-sampled fluid, so beta = 2 dt^2 spacing^6.
  const double v = double(spacing) * spacing * spacing;
  return 1.0 / (2.0 * v * v * denominator);
}

void PcisphSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  Particles& p = world.particles();
  predicted_position_ = p.declare_position_vector(kPredictedPosition);
  predicted_density_ = p.declare_scalar(kPredictedDensity);
  scaled_pressure_ = p.declare_scratch_scalar(kScaledPressure);
  reference_speed_ = free_fall_speed(world);
  delta_scale_ = template_delta_scale(world.settings().spacing, world.kernel());
  // rest_compression eta = kRestCompression g H (dt / s)^2 with g H = v_ref^2 / 2.
  rest_time_step_ = reference_speed_ > 0 && rest_compression_ > 0
                        ? Real(double(world.settings().spacing) / double(reference_speed_) *
                               std::sqrt(2 * rest_compression_ * eta_ / kRestCompression))
                        : Real(0);
}

Real PcisphSolver::max_time_step(const World& world) const {
  const Real dt = fluid_cfl_time_step(world, fluid_.force_limits(), reference_speed_);
  return rest_time_step_ > 0 ? std::min(dt, rest_time_step_) : dt;
}

std::vector<std::string> PcisphSolver::stages() const {
  return {"non_pressure", "pressure", "integration"};
}

void PcisphSolver::step(World& world, Real dt, StageRunner& run) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  FluidView f;
  Real* density = nullptr;
  Real* pressure = nullptr;
  stats_ = SolverStats{};

  // Non-pressure forces: density and kernel gradients at the current positions, then gravity +
  // viscosity. Pressures start from zero.
  run("non_pressure", [&] {
    f = fluid_.begin_step(world);
    density = p[fluid_.density_field].data();
    pressure = p[fluid_.pressure_field].data();
    fluid_.shared_forces(world, f, density, dt);
    exec.run(fluid_.owned.range(), ClearPressureStage{pressure, fluid_.pressure_acceleration});
  });

  // Predict-correct loop. Particles this solver does not move (boundaries, bodies, other
  // fluids) are predicted once, moving on at their current velocity; static walls stay put.
  run("pressure", [&] {
    Real* rho_star = p[predicted_density_].data();
    Vec3* x_star = p[predicted_position_].data();
    fluid_.predict_unowned(world, f, x_star, dt);
    PcisphLoopArrays arrays{f,
                            fluid_.owned.range(),
                            fluid_.other_acceleration.data(),
                            fluid_.fluid_gradient.data(),
                            fluid_.boundary_gradient.data(),
                            fluid_.pressure_acceleration,
                            x_star,
                            rho_star,
                            pressure,
                            p[scaled_pressure_].data(),
                            nullptr};
    if (f.density_contrast) {
      contrast_ratio_.resize(p.size());
      arrays.contrast_ratio = contrast_ratio_.data();
    }
    stats_ = pcisph_correction_loop(
        exec, arrays, loop_settings(), dt,
        [&](const CompressionValue&) { return stopping_(exec, fluid_.owned, f, rho_star); });
  });

  // Reactions on rigid bodies, then symplectic Euler with the final pressure forces.
  run("integration", [&] {
    fluid_.add_reactions(world, f, density,
                         PressureOverRestDensitySquared{pressure, f.rest_density, f.material});
    fluid_.integrate(world, dt);
  });
}

}  // namespace upf
