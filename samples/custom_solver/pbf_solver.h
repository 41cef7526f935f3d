// Position Based Fluids: Macklin & Müller 2013, "Position Based Fluids", ACM TOG 32(4),
// SIGGRAPH 2013 (the fluid method of NVIDIA FleX). A sample of a solver added from outside the
// framework: this folder is compiled into `upf` through UPF_EXTENSION_DIRS (docs/extending.md).
//
// One step (the paper's Algorithm 1):
//   1 predict: v* = v + dt (g + shared viscosity),  x* = x + dt v*
//   2 `iterations` times, Jacobi style: lambda_i from the density constraint C_i = rho_i/rho0 - 1
//     at x*, then every dx_i from the lambdas and the artificial pressure s_corr, then x* += dx
//     (formulas in pbf_kernels.h)
//   3 v = (x* - x) / dt,  x = x*; x* - x is kept as its own sum (the prediction's v* dt plus
//     every correction), not taken as a difference of positions: at 0.5 m from the origin a
//     float position is good to 3e-8 m, which at dt = 0.4 ms is a velocity noise of 1e-4 m/s per
//     particle and step, enough to break momentum conservation by far more than the coupling
//     forces exchange (measured: 0.0176 kg m/s in 100 steps of a floating block at rest)
//   4 XSPH viscosity and, when `vorticity` > 0, vorticity confinement on the new velocities
// Boundaries are frozen and rigid particles with Akinci et al. 2012 volumes, shared with every
// fluid solver: they add to the density and to grad_i C_i and are not moved by the corrections
// (inverse mass 0); moving bodies are seen where they will be, x + v dt, as PCISPH sees them.
//
// Coupling, through the pieces every fluid solver shares (solvers/fluid/fluid_solver_state.h):
// the force of grains on the liquid joins gravity and viscosity in the prediction, and bodies get
// the reaction of every correction a boundary particle b causes: particle i moves by
// lambda_i V_b grad W_ib per iteration, a momentum m_i dx / dt over the step, so b receives
//   F_b = -sum_i m_i lambda_i V_b grad W(x*_i - x*_b) / dt^2,
// summed over the iterations (and the shared viscosity's reaction). Fluid and bodies together
// conserve momentum.
//
// Neighbour lists. The paper finds neighbours once per step, at the positions predicted with
// gravity, and keeps them through the iterations while the corrections move the particles on.
// Here the lists are those the world builds at the start of the step, at x, as for PCISPH. Under
// the CFL limit a particle moves at most cfl * spacing = 0.2 H per step (cfl = 0.4, H = 2
// spacing), so a pair that is not in the lists ends the prediction at least 0.8 H apart when one
// of them is at rest (a wall), where the cubic spline is 1.6 % of its peak, and the typical
// neighbour moves with its neighbours. The approximation is of the same order as the paper's own,
// and a larger search radius would cost every solver in the world. The CFL limit is kept for
// that reason and for accuracy: PBF is stable at any dt, but its compression grows as dt^2.
//
// Pressure. PBF has none, but its corrections are pressure accelerations in disguise: the
// symmetric SPH pressure term with Akinci's boundary term, times dt^2, is dx_i of eq. 12 with
// lambda_i = -dt^2 p_i / rho0. The exported field "pressure" is therefore -rho0 sum lambda / dt^2
// over the iterations of the step (zero where nothing is compressed, as PCISPH's), so pressure
// probes and comparisons with PCISPH work unchanged.
//
// Units: masses are real (m = rho0 h^3), so the paper's epsilon and k are made dimensionless
// here, relative to the denominator of eq. 11 for a particle with a full neighbourhood on the
// initial lattice (see param_binding()). Only compression is corrected by default (unilateral):
// with the bilateral constraint of the paper, particles at the free surface, which lack
// neighbours, pull towards the liquid and clump (SPlisHSPlasH's PBF clamps in the same way).
#pragma once

#include <cstdint>
#include <vector>

#include "framework/params/param_binding.h"
#include "framework/solver/solver.h"
#include "pbf_kernels.h"
#include "solvers/fluid/fluid_solver_state.h"

namespace upf::pbf {

struct PbfParams {
  int iterations = 0;
  double relaxation = 0, tensile_k = 0, tensile_dq = 0, xsph = 0, vorticity = 0;
  int tensile_n = 0;
  bool unilateral = true;
};

class PbfSolver final : public Solver {
 public:
  PbfSolver(const PbfParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override { return "pbf"; }
  void prepare(World& world) override;
  void initialize_fields(World& world) override { fluid_.initial_density(world); }
  Real max_time_step(const World& world) const override;
  std::vector<std::string> stages() const override;
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override { return fluid_.with_viscosity(stats_); }

  static ParamBinding<PbfParams> param_binding();
  // The denominator of eq. 11 for a particle with a full neighbourhood on a cubic lattice of
  // `spacing` with volumes spacing^3: the unit in which `relaxation` and `tensile_k` are given.
  static double template_denominator(Real spacing, const CubicSplineKernel& kernel);

 private:
  void predict(World& world, const FluidView& f, Real dt);
  void solve_constraints(World& world, const FluidView& f, Real dt);
  void update_velocities(World& world, const FluidView& f, Real dt);
  // Adds the reactions of this iteration's boundary corrections to the bodies' particles.
  void add_correction_reactions(World& world, const FluidView& f, const Vec3* xs,
                                const Real* lambda, Real dt) const;

  int iterations_;
  double relaxation_, tensile_k_, tensile_dq_, xsph_, vorticity_;
  int tensile_n_;
  bool unilateral_;
  std::vector<MaterialId> materials_;
  FluidSolverState fluid_;  // owned particles, lists, materials, shared forces, reactions
  struct Fields {
    FieldHandle<Real> lambda, predicted_density;
    FieldHandle<Vec3> predicted_position, position_correction, displacement, boundary_gradient,
        velocity, vorticity;
  } fields_;
  PbfConstants constants_;
  Real reference_speed_ = 0;  // sqrt(2 g H) of the initial liquid, for the CFL limit
  SolverStats stats_;
  std::vector<Vec3> pair_gradient_;  // grad W_ij per fluid-list slot at x*, for one iteration
  std::vector<Real> pair_tensile_;   // s_corr per fluid-list slot at x*, for one iteration
};

}  // namespace upf::pbf
