#include "pbf_solver.h"

#include <algorithm>
#include <cmath>

#include "framework/core/stopwatch.h"
#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_time_step.h"

namespace upf::pbf {

std::vector<ParamSpec> PbfSolver::param_specs() {
  return {
      {"iterations", "1", 4, 1, 1000,
       "density-constraint iterations per step (the paper's solverIterations; it uses 2-4)", true},
      {"relaxation", "1", 1e-3, 0, 100,
       "epsilon of lambda's denominator (constraint force mixing), as a fraction of a full "
       "neighbourhood's denominator: softens the constraint where neighbours are few"},
      {"tensile_k", "1", 0.1, 0, 10,
       "k of the artificial pressure s_corr = -k (W(r)/W(dq))^n, as the lambda of a density "
       "error of k in a full neighbourhood; 0 switches it off"},
      {"tensile_n", "1", 4, 1, 16, "exponent n of the artificial pressure", true},
      {"tensile_dq", "1", 0.2, 0.01, 0.99,
       "dq / H of the artificial pressure (the distance where s_corr = -k)"},
      {"xsph", "1", 0.01, 0, 1,
       "XSPH viscosity c: each step blends c of the neighbours' kernel-weighted velocity in"},
      {"vorticity", "m/s", 0, 0, 100,
       "vorticity confinement epsilon: feeds back rotation lost to damping; 0 switches it off"},
      {"unilateral", "1", 1, 0, 1,
       "1: correct compression only, C = max(rho/rho0 - 1, 0); 0: the paper's two-sided "
       "constraint, which also pulls particles together and needs relaxation >= 1 to stay "
       "stable at the free surface",
       true},
  };
}

PbfSolver::PbfSolver(const ParamValues& params, std::vector<MaterialId> materials)
    : iterations_(int(params.get("iterations"))),
      relaxation_(params.get("relaxation")),
      tensile_k_(params.get("tensile_k")),
      tensile_dq_(params.get("tensile_dq")),
      xsph_(params.get("xsph")),
      vorticity_(params.get("vorticity")),
      tensile_n_(int(params.get("tensile_n"))),
      unilateral_(params.get("unilateral") != 0),
      materials_(std::move(materials)) {}

double PbfSolver::template_denominator(Real spacing, const CubicSplineKernel& kernel) {
  // A particle with a full neighbourhood on the initial cubic lattice, volumes spacing^3.
  const int reach = int(std::ceil(kernel.support_radius() / spacing));
  const double v = double(spacing) * spacing * spacing;
  double gx = 0, gy = 0, gz = 0, sum_grad2 = 0;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = -reach; k <= reach; ++k) {
        const Vec3 g = kernel.gradient({Real(i) * spacing, Real(j) * spacing, Real(k) * spacing});
        gx += v * double(g.x);
        gy += v * double(g.y);
        gz += v * double(g.z);
        sum_grad2 += v * v * double(squared_norm(g));
      }
  return gx * gx + gy * gy + gz * gz + sum_grad2;
}

void PbfSolver::prepare(World& world) {
  fluid_.prepare(world, materials_);
  Particles& p = world.particles();
  p.scalar_field("pbf.lambda", 0, true);
  p.scalar_field("pbf.predicted_density");
  p.vector_field("pbf.predicted_position");
  p.vector_field("pbf.position_correction");
  p.vector_field("pbf.displacement");
  p.vector_field("pbf.boundary_gradient");
  p.vector_field("pbf.velocity");
  p.vector_field("pbf.vorticity");
  reference_speed_ = free_fall_speed(world);

  // The paper's epsilon and k, which assume unit masses, in SI units for this spacing.
  const CubicSplineKernel kernel = world.kernel();
  const double denominator = template_denominator(world.settings().spacing, kernel);
  constants_.relaxation = Real(relaxation_ * denominator);
  constants_.tensile_scale = Real(tensile_k_ / denominator);
  constants_.tensile_inv_reference =
      Real(1) / kernel.value(Real(tensile_dq_) * kernel.support_radius());
  constants_.tensile_exponent = tensile_n_;
  constants_.unilateral = unilateral_;
}

Real PbfSolver::max_time_step(const World& world) const {
  return fluid_cfl_time_step(world, fluid_.max_viscosity, reference_speed_);
}

template <class Body>
void PbfSolver::for_mine(const World& world, Body&& body) const {
  fluid_.owned.for_each(world.executor(), body);
}

void PbfSolver::predict(World& world, const FluidView& f, Real dt) {
  Particles& p = world.particles();
  Real* density = p.scalar_field("density").data();
  Vec3* xs = p.vector_field("pbf.predicted_position").data();
  const Vec3* x = p.position.data();
  Vec3* disp = p.vector_field("pbf.displacement").data();
  const Vec3* a_other = fluid_.other_acceleration.data();

  // The density at x is what frames show as "density" (as for the other fluid solvers); the
  // shared forces: gravity, viscosity and the force of other materials (grains).
  fluid_.shared_forces(world, f, density);
  // Particles this solver does not move at their velocity, the owned ones under the forces.
  fluid_.predict_unowned(world, f, xs, dt);
  for_mine(world, [&](std::uint32_t i) {
    const Vec3 v = f.v[i] + a_other[i] * dt;
    disp[i] = v * dt;
    xs[i] = x[i] + disp[i];
  });
  // The shared viscosity's reaction on bodies (no pressure term: the corrections add theirs).
  fluid_.add_reactions(world, f, density, [](std::uint32_t) { return Real(0); });
}

void PbfSolver::add_correction_reactions(World& world, const FluidView& f, const Vec3* xs,
                                         const Real* lambda, Real dt) const {
  if (fluid_.reaction_list < 0) return;
  const NeighbourView fluid_of_body = view_of(world.neighbours(fluid_.reaction_list));
  Vec3* force = world.coupling()[CouplingArray::BoundaryForce].data();
  const OwnedParticles& owned = fluid_.owned;
  const Real inv_dt2 = Real(1) / (dt * dt);
  world.executor().for_each(world.particles().size(), [&](std::size_t b) {
    const std::uint32_t begin = fluid_of_body.offsets[b];
    const std::uint32_t end = fluid_of_body.offsets[b + 1];
    if (begin == end) return;
    Vec3 sum{};
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = fluid_of_body.indices[k];
      if (!owned.owns(f.material[i])) continue;
      sum -= f.kernel.gradient(xs[i] - xs[b]) * (f.mass[i] * lambda[i]);
    }
    force[b] += sum * (f.boundary_volume[b] * inv_dt2);
  });
}

void PbfSolver::solve_constraints(World& world, const FluidView& f, Real dt) {
  Particles& p = world.particles();
  Real* pressure = p.scalar_field("pressure").data();
  Real* lambda = p.scalar_field("pbf.lambda").data();
  Real* rho = p.scalar_field("pbf.predicted_density").data();
  Vec3* xs = p.vector_field("pbf.predicted_position").data();
  Vec3* dx = p.vector_field("pbf.position_correction").data();
  Vec3* disp = p.vector_field("pbf.displacement").data();
  const std::size_t slots = world.neighbours(fluid_.lists.fluid).total();
  pair_gradient_.resize(slots);
  pair_tensile_.resize(slots);
  const PbfPairTerms terms{pair_gradient_.data(), pair_tensile_.data(),
                           p.vector_field("pbf.boundary_gradient").data(), rho};
  const PbfConstants c = constants_;
  const Real inv_dt2 = Real(1) / (dt * dt);
  for_mine(world, [&](std::uint32_t i) { pressure[i] = 0; });

  // Jacobi: every lambda from the same x*, every dx from the same lambdas, then all moves.
  for (int iteration = 0; iteration < iterations_; ++iteration) {
    for_mine(world, [&](std::uint32_t i) {
      lambda[i] = pbf_lambda(f, xs, c, terms, i);
      pressure[i] -= f.rest_density[f.material[i]] * lambda[i] * inv_dt2;
    });
    add_correction_reactions(world, f, xs, lambda, dt);
    for_mine(world, [&](std::uint32_t i) { dx[i] = pbf_position_correction(f, lambda, terms, i); });
    for_mine(world, [&](std::uint32_t i) {
      xs[i] += dx[i];
      disp[i] += dx[i];
    });
  }

  // The density error of the last iteration, defined as for every fluid solver
  // (solvers/fluid/compression_stats.h).
  stats_.iterations = iterations_;
  stats_.avg_density_error = average_compression(world.executor(), fluid_.owned, f, rho);
  stats_.max_density_error = max_compression(world.executor(), fluid_.owned, f, rho);
}

void PbfSolver::update_velocities(World& world, const FluidView& f, Real dt) {
  Particles& p = world.particles();
  Vec3* x = p.position.data();
  Vec3* v = p.velocity.data();
  const Vec3* xs = p.vector_field("pbf.predicted_position").data();
  const Vec3* disp = p.vector_field("pbf.displacement").data();
  Vec3* v_new = p.vector_field("pbf.velocity").data();
  Vec3* omega = p.vector_field("pbf.vorticity").data();

  for_mine(world, [&](std::uint32_t i) {
    v[i] = disp[i] / dt;
    x[i] = xs[i];
  });
  // f views the particle arrays, so from here on it sees the new positions and velocities.
  // XSPH and confinement read the neighbours' new velocities: results go to a scratch field
  // first so that no particle reads a velocity already smoothed this step.
  const Real c = Real(xsph_), epsilon = Real(vorticity_);
  for_mine(world, [&](std::uint32_t i) {
    const PbfVelocityTerms t = pbf_velocity_terms(f, c, i);
    v_new[i] = t.xsph;
    omega[i] = t.omega;
  });
  if (epsilon > 0)
    for_mine(world, [&](std::uint32_t i) {
      v_new[i] += pbf_vorticity_acceleration(f, omega, epsilon, i) * dt;
    });
  for_mine(world, [&](std::uint32_t i) { v[i] = v_new[i]; });
}

void PbfSolver::step(World& world, Real dt) {
  const FluidView f = fluid_.begin_step(world);

  Stopwatch watch;
  stats_ = SolverStats{};
  predict(world, f, dt);
  stats_.stage_ms.emplace_back("predict", watch.lap_ms());
  solve_constraints(world, f, dt);
  stats_.stage_ms.emplace_back("constraints", watch.lap_ms());
  update_velocities(world, f, dt);
  stats_.stage_ms.emplace_back("velocity", watch.lap_ms());
}

}  // namespace upf::pbf
