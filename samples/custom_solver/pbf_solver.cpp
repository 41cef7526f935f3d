#include "pbf_solver.h"

#include <algorithm>
#include <cmath>

#include "framework/world/world.h"
#include "pbf_stages.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_forces.h"
#include "solvers/fluid/fluid_time_step.h"

namespace upf::pbf {

ParamBinding<PbfParams> PbfSolver::param_binding() {
  ParamBinding<PbfParams> b;
  b.add({"iterations", "1", 4, 1, 1000,
         "density-constraint iterations per step (the paper's solverIterations; it uses 2-4)"},
        &PbfParams::iterations);
  b.add({"relaxation", "1", 1e-3, 0, 100,
         "epsilon of lambda's denominator (constraint force mixing), as a fraction of a full "
         "neighbourhood's denominator: softens the constraint where neighbours are few"},
        &PbfParams::relaxation);
  b.add({"tensile_k", "1", 0.1, 0, 10,
         "k of the artificial pressure s_corr = -k (W(r)/W(dq))^n, as the lambda of a density "
         "error of k in a full neighbourhood; 0 switches it off"},
        &PbfParams::tensile_k);
  b.add({"tensile_n", "1", 4, 1, 16, "exponent n of the artificial pressure"},
        &PbfParams::tensile_n);
  b.add({"tensile_dq", "1", 0.2, 0.01, 0.99,
         "dq / H of the artificial pressure (the distance where s_corr = -k)"},
        &PbfParams::tensile_dq);
  b.add({"xsph", "1", 0.01, 0, 1,
         "XSPH viscosity c: each step blends c of the neighbours' kernel-weighted velocity in"},
        &PbfParams::xsph);
  b.add({"vorticity", "m/s", 0, 0, 100,
         "vorticity confinement epsilon: feeds back rotation lost to damping; 0 switches it off"},
        &PbfParams::vorticity);
  b.add({"unilateral", "1", 1, 0, 1,
         "1: correct compression only, C = max(rho/rho0 - 1, 0); 0: the paper's two-sided "
         "constraint, which also pulls particles together and needs relaxation >= 1 to stay "
         "stable at the free surface"},
        &PbfParams::unilateral);
  return b;
}

PbfSolver::PbfSolver(const PbfParams& params, std::vector<MaterialId> materials)
    : iterations_(params.iterations),
      relaxation_(params.relaxation),
      tensile_k_(params.tensile_k),
      tensile_dq_(params.tensile_dq),
      xsph_(params.xsph),
      vorticity_(params.vorticity),
      tensile_n_(params.tensile_n),
      unilateral_(params.unilateral),
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
  fields_.lambda = p.declare_scalar("pbf.lambda", 0, true);
  fields_.predicted_density = p.declare_scalar("pbf.predicted_density");
  fields_.predicted_position = p.declare_position_vector("pbf.predicted_position");
  fields_.position_correction = p.declare_vector("pbf.position_correction");
  fields_.displacement = p.declare_vector("pbf.displacement");
  fields_.boundary_gradient = p.declare_vector("pbf.boundary_gradient");
  fields_.velocity = p.declare_vector("pbf.velocity");
  fields_.vorticity = p.declare_vector("pbf.vorticity");
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
  return fluid_cfl_time_step(world, fluid_.force_limits(), reference_speed_);
}

void PbfSolver::predict(World& world, const FluidView& f, Real dt) {
  Particles& p = world.particles();
  Real* density = p[fluid_.density_field].data();
  Vec3* xs = p[fields_.predicted_position].data();

  // The density at x is what frames show as "density" (as for the other fluid solvers); the
  // shared forces: gravity, viscosity and the force of other materials (grains).
  fluid_.shared_forces(world, f, density, dt);
  // Particles this solver does not move at their velocity, the owned ones under the forces.
  fluid_.predict_unowned(world, f, xs, dt);
  world.executor().run(
      fluid_.owned.range(),
      PbfPredictStage{f, fluid_.other_acceleration.data(), dt, p[fields_.displacement].data(), xs});
  // The shared viscosity's reaction on bodies (no pressure term: the corrections add theirs).
  fluid_.add_reactions(world, f, density, NoPressureFactor{});
}

void PbfSolver::add_correction_reactions(World& world, const FluidView& f, const Vec3* xs,
                                         const Real* lambda, Real dt) const {
  if (fluid_.reaction_list < 0) return;
  world.executor().run(
      all_particles(world.particles().size()),
      PbfCorrectionReactionStage{f, view_of(world.neighbours(fluid_.reaction_list)),
                                 fluid_.owned.materials(), xs, lambda, Real(1) / (dt * dt),
                                 world.coupling()[CouplingArray::BoundaryForce].data()});
}

void PbfSolver::solve_constraints(World& world, const FluidView& f, Real dt) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const ParticleRange mine = fluid_.owned.range();
  Real* pressure = p[fluid_.pressure_field].data();
  Real* lambda = p[fields_.lambda].data();
  Real* rho = p[fields_.predicted_density].data();
  Vec3* xs = p[fields_.predicted_position].data();
  Vec3* dx = p[fields_.position_correction].data();
  Vec3* disp = p[fields_.displacement].data();
  const std::size_t slots = world.neighbours(fluid_.lists.fluid).total();
  pair_gradient_.resize(slots);
  pair_tensile_.resize(slots);
  const PbfPairTerms terms{pair_gradient_.data(), pair_tensile_.data(),
                           p[fields_.boundary_gradient].data(), rho};
  const Real inv_dt2 = Real(1) / (dt * dt);
  exec.run(mine, ZeroScalarStage{pressure});

  // Jacobi: every lambda from the same x*, every dx from the same lambdas, then all moves.
  const PbfLambdaStage lambdas{f, xs, constants_, terms, inv_dt2, lambda, pressure};
  const PbfCorrectionStage corrections{f, lambda, terms, dx};
  const PbfApplyCorrectionStage moves{dx, xs, disp};
  for (int iteration = 0; iteration < iterations_; ++iteration) {
    exec.run(mine, lambdas);
    add_correction_reactions(world, f, xs, lambda, dt);
    exec.run(mine, corrections);
    exec.run(mine, moves);
  }

  // The density error of the last iteration, defined as for every fluid solver
  // (solvers/fluid/compression_stats.h).
  stats_.iterations = iterations_;
  stats_.avg_density_error = average_compression(exec, fluid_.owned, f, rho);
  stats_.max_density_error = max_compression(exec, fluid_.owned, f, rho);
}

void PbfSolver::update_velocities(World& world, const FluidView& f, Real dt) {
  Particles& p = world.particles();
  const CpuExecutor& exec = world.executor();
  const ParticleRange mine = fluid_.owned.range();
  Vec3* v = p.velocity.data();
  Vec3* v_new = p[fields_.velocity].data();
  Vec3* omega = p[fields_.vorticity].data();

  exec.run(mine, PbfTakePredictionStage{p[fields_.predicted_position].data(),
                                        p[fields_.displacement].data(), dt, p.position.data(), v});
  // f views the particle arrays, so from here on it sees the new positions and velocities.
  // XSPH and confinement read the neighbours' new velocities: results go to a scratch field
  // first so that no particle reads a velocity already smoothed this step.
  exec.run(mine, PbfVelocityTermsStage{f, Real(xsph_), v_new, omega});
  if (const Real epsilon = Real(vorticity_); epsilon > 0)
    exec.run(mine, PbfVorticityStage{f, omega, epsilon, dt, v_new});
  exec.run(mine, CopyVectorStage{v_new, v});
}

std::vector<std::string> PbfSolver::stages() const {
  return {"predict", "constraints", "velocity"};
}

void PbfSolver::step(World& world, Real dt, StageRunner& run) {
  FluidView f;
  stats_ = SolverStats{};
  run("predict", [&] {
    f = fluid_.begin_step(world);
    predict(world, f, dt);
  });
  run("constraints", [&] { solve_constraints(world, f, dt); });
  run("velocity", [&] { update_velocities(world, f, dt); });
}

}  // namespace upf::pbf
