#include "solvers/pcisph/pcisph_solver.h"

#include <algorithm>
#include <cmath>

#include "framework/core/deterministic_sum.h"
#include "framework/core/stopwatch.h"
#include "framework/world/world.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/pcisph/pcisph_kernels.h"

namespace upf {

std::vector<ParamSpec> PcisphSolver::param_specs() {
  return {
      {"eta", "1", 0.01, 1e-6, 0.5,
       "target average compression (rho - rho0)/rho0 that ends the correction loop"},
      {"min_iterations", "1", 3, 1, 1000, "correction iterations always done", true},
      {"max_iterations", "1", 100, 1, 10000, "correction iterations at most", true},
  };
}

PcisphSolver::PcisphSolver(const ParamValues& params, std::vector<MaterialId> materials)
    : eta_(params.get("eta")),
      min_iterations_(int(params.get("min_iterations"))),
      max_iterations_(int(params.get("max_iterations"))),
      materials_(std::move(materials)) {}

double PcisphSolver::template_delta_scale(Real spacing, const CubicSplineKernel& kernel) {
  // A particle with a full neighbourhood on the initial cubic lattice.
  const int reach = int(std::ceil(kernel.support_radius() / spacing));
  Vec3 sum_grad{};
  double sum_grad2 = 0;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = -reach; k <= reach; ++k) {
        const Vec3 r{Real(i) * spacing, Real(j) * spacing, Real(k) * spacing};
        const Vec3 g = kernel.gradient(r);
        sum_grad += g;
        sum_grad2 += double(squared_norm(g));
      }
  const double denominator = double(squared_norm(sum_grad)) + sum_grad2;
  // m / rho0 = spacing^3 for lattice-sampled fluid, so beta = 2 dt^2 spacing^6.
  const double v = double(spacing) * spacing * spacing;
  return 1.0 / (2.0 * v * v * denominator);
}

void PcisphSolver::prepare(World& world) {
  Particles& p = world.particles();
  p.scalar_field("density", 0, true);
  p.scalar_field("pressure", 0, true);
  p.vector_field("pcisph.predicted_position");
  p.vector_field("pcisph.pressure_acceleration");
  p.vector_field("pcisph.other_acceleration");
  p.vector_field("pcisph.boundary_gradient");
  p.scalar_field("pcisph.predicted_density");
  lists_.request(world);
  table_.load(world);
  owns_.assign(world.materials().size(), 0);
  for (MaterialId m : materials_) owns_[m] = 1;
  max_viscosity_ = 0;
  for (MaterialId m : materials_) max_viscosity_ = std::max(max_viscosity_, table_.viscosity[m]);
  reference_speed_ = free_fall_speed(world);
  delta_scale_ = template_delta_scale(world.settings().spacing, world.kernel());
}

Real PcisphSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, max_viscosity_, reference_speed_);
}

void PcisphSolver::step(World& world, Real dt) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const std::size_t n = p.size();
  const FluidView f = make_fluid_view(world, table_, lists_);
  const ParticleType* type = p.type.data();
  const Vec3 g = world.settings().gravity;

  Real* density = p.scalar_field("density").data();
  Real* pressure = p.scalar_field("pressure").data();
  Real* rho_star = p.scalar_field("pcisph.predicted_density").data();
  Vec3* x_star = p.vector_field("pcisph.predicted_position").data();
  Vec3* a_p = p.vector_field("pcisph.pressure_acceleration").data();
  Vec3* a_other = p.vector_field("pcisph.other_acceleration").data();
  Vec3* boundary_gradient = p.vector_field("pcisph.boundary_gradient").data();
  fluid_gradient_.resize(world.neighbours(lists_.fluid).total());
  Vec3* fluid_gradient = fluid_gradient_.data();
  // The particles this solver moves, as an index list: loops over it split evenly between
  // threads (a static split of all particles did not: walls and water sit in different parts of
  // the Morton order, and one thread waited for the other).
  mine_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (type[i] == ParticleType::Liquid && owns_[p.material[i]]) mine_.push_back(std::uint32_t(i));
  const std::uint32_t* mine = mine_.data();
  auto for_mine = [&](auto&& body) {
    exec.for_each(mine_.size(), [&](std::size_t k) { body(mine[k]); });
  };

  Stopwatch watch;
  stats_ = SolverStats{};

  // Non-pressure forces: density and kernel gradients at the current positions, then gravity +
  // viscosity.
  for_mine([&](std::uint32_t i) {
    density[i] = density_and_gradients(f, fluid_gradient, boundary_gradient[i], i);
  });
  for_mine([&](std::uint32_t i) {
    a_other[i] = g + viscosity_acceleration(f, density, fluid_gradient, i);
    pressure[i] = 0;
    a_p[i] = Vec3{};
  });
  stats_.stage_ms.emplace_back("non_pressure", watch.lap_ms());

  // Predict-correct loop.
  const double delta = delta_scale_ / (double(dt) * double(dt));
  double avg_error = 0;
  int iteration = 0;
  auto relative_error = [&](std::uint32_t i) {
    const Real rho0 = f.rest_density[f.material[i]];
    return (rho_star[i] - rho0) / rho0;
  };
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
    const double error_sum = fixed_point_sum(exec, mine_.size(), [&](std::size_t k) {
      return std::max(0.0, double(relative_error(mine[k])));
    });
    avg_error = mine_.empty() ? 0.0 : error_sum / double(mine_.size());
    for_mine([&](std::uint32_t i) {
      a_p[i] = pcisph_pressure_acceleration(f, pressure, fluid_gradient, boundary_gradient[i], i);
    });
    ++iteration;
    if (iteration >= min_iterations_ && avg_error <= eta_) break;
  }
  stats_.iterations = iteration;
  stats_.avg_density_error = avg_error;
  Real max_error = 0;
  const std::int64_t count = std::int64_t(mine_.size());
#pragma omp parallel for schedule(static) reduction(max : max_error) num_threads(exec.threads())
  for (std::int64_t k = 0; k < count; ++k) max_error = std::max(max_error, relative_error(mine[k]));
  stats_.max_density_error = double(max_error);
  stats_.stage_ms.emplace_back("pressure", watch.lap_ms());

  // Symplectic Euler with the final pressure forces.
  Vec3* v = p.velocity.data();
  Vec3* x = p.position.data();
  for_mine([&](std::uint32_t i) {
    v[i] += (a_other[i] + a_p[i]) * dt;
    x[i] += v[i] * dt;
  });
  stats_.stage_ms.emplace_back("integration", watch.lap_ms());
}

}  // namespace upf
