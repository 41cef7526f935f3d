#include "solvers/pcisph/pcisph_solver.h"

#include <algorithm>
#include <cmath>

#include "framework/core/stopwatch.h"
#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/fluid/lattice_template.h"
#include "solvers/pcisph/pcisph_kernels.h"

namespace upf {

std::vector<ParamSpec> PcisphSolver::param_specs() {
  return {
      {"eta", "1", 0.01, 1e-6, 0.5,
       "target average compression (rho - rho0)/rho0: the correction loop ends once the average "
       "falls below it"},
      {"min_iterations", "1", 3, 1, 1000, "correction iterations always done", true},
      {"max_iterations", "1", 100, 1, 10000,
       "correction iterations at most; not checked against min_iterations: if min_iterations > "
       "max_iterations, the loop stops at max_iterations",
       true},
  };
}

PcisphSolver::PcisphSolver(const ParamValues& params, std::vector<MaterialId> materials)
    : eta_(params.get("eta")),
      min_iterations_(int(params.get("min_iterations"))),
      max_iterations_(int(params.get("max_iterations"))),
      materials_(std::move(materials)) {}

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
  p.vector_field("pcisph.predicted_position");
  p.scalar_field("pcisph.predicted_density");
  reference_speed_ = free_fall_speed(world);
  delta_scale_ = template_delta_scale(world.settings().spacing, world.kernel());
}

Real PcisphSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, fluid_.max_viscosity, reference_speed_);
}

void PcisphSolver::step(World& world, Real dt) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const FluidView f = fluid_.begin_step(world);
  const OwnedParticles& owned = fluid_.owned;
  auto for_mine = [&](auto&& body) { owned.for_each(exec, body); };

  Real* density = p.scalar_field("density").data();
  Real* pressure = p.scalar_field("pressure").data();
  Real* rho_star = p.scalar_field("pcisph.predicted_density").data();
  Vec3* x_star = p.vector_field("pcisph.predicted_position").data();
  Vec3* a_p = fluid_.pressure_acceleration.data();
  const Vec3* a_other = fluid_.other_acceleration.data();
  const Vec3* boundary_gradient = fluid_.boundary_gradient.data();
  const Vec3* fluid_gradient = fluid_.fluid_gradient.data();

  Stopwatch watch;
  stats_ = SolverStats{};

  // Non-pressure forces: density and kernel gradients at the current positions, then gravity +
  // viscosity. Pressures start from zero.
  fluid_.shared_forces(world, f, density);
  for_mine([&](std::uint32_t i) {
    pressure[i] = 0;
    a_p[i] = Vec3{};
  });
  stats_.stage_ms.emplace_back("non_pressure", watch.lap_ms());

  // Predict-correct loop. Particles this solver does not move (boundaries, bodies, other
  // fluids) are predicted once, moving on at their current velocity; static walls stay put.
  fluid_.predict_unowned(world, f, x_star, dt);
  const double delta = delta_scale_ / (double(dt) * double(dt));
  double avg_error = 0;
  int iteration = 0;
  while (iteration < max_iterations_) {
    for_mine([&](std::uint32_t i) {
      const Vec3 v_star = f.v[i] + (a_other[i] + a_p[i]) * dt;
      x_star[i] = f.x[i] + v_star * dt;
    });
    for_mine([&](std::uint32_t i) {
      rho_star[i] = fluid_density(f, x_star, i);
      const Real rho0 = f.rest_density[f.material[i]];
      pressure[i] = std::max(Real(0), pressure[i] + Real(delta) * (rho_star[i] - rho0));
    });
    // The stopping test sums in fixed point: the same iteration count for any thread count.
    avg_error = average_compression(exec, owned, f, rho_star);
    for_mine([&](std::uint32_t i) {
      a_p[i] = pcisph_pressure_acceleration(f, pressure, fluid_gradient, boundary_gradient[i], i);
    });
    ++iteration;
    if (iteration >= min_iterations_ && avg_error <= eta_) break;
  }
  stats_.iterations = iteration;
  stats_.avg_density_error = avg_error;
  stats_.max_density_error = max_compression(exec, owned, f, rho_star);
  stats_.stage_ms.emplace_back("pressure", watch.lap_ms());

  // Reactions on rigid bodies, then symplectic Euler with the final pressure forces.
  fluid_.add_reactions(world, f, density, [&](std::uint32_t i) {
    const Real rho0 = f.rest_density[f.material[i]];
    return pressure[i] / (rho0 * rho0);
  });
  fluid_.integrate(world, dt);
  stats_.stage_ms.emplace_back("integration", watch.lap_ms());
}

}  // namespace upf
