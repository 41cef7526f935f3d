// DFSPH's step (Bender & Koschier 2015, 2017; dfsph_solver.h) after the shared forces, written
// once for every executor: DfsphSolver runs it on the CPU executor, the device pipeline on its
// backends (device/). Plain views and an executor with run / fixed_point_sum / max_of, so the
// same statements give the same bits wherever they run. C++17: nvcc builds it too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "framework/executors/average_over.h"
#include "framework/executors/particle_range.h"
#include "framework/solver/solver.h"
#include "solvers/dfsph/dfsph_kernels.h"
#include "solvers/dfsph/dfsph_summed_density.h"
#include "solvers/fluid/density_rate.h"
#include "solvers/fluid/fluid_stages.h"

namespace upf {

struct DfsphArrays {
  FluidView f;
  ParticleRange owned;
  std::size_t n;  // all particles
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Vec3* other_acceleration;
  const Real* density;
  Real* density_stiffness;     // the fields: last step's K / dt^2 in, this step's out
  Real* divergence_stiffness;  // K / dt, likewise
  // Per-step work arrays over all particles.
  Real* factor;
  Real* boundary_divergence;
  Real* rho_adv;
  Real* k;
  Real* k_total;
  Vec3* v_star;
  // With DfsphSettings::summed_density_check (else null): the predicted positions and the
  // densities summed there, and the density the linear prediction starts from.
  Vec3* x_star = nullptr;
  Real* rho_star = nullptr;
  Real* rho_base = nullptr;
};

// The scratch fields that hold the work arrays (DfsphSolver declares them; the device pipeline
// binds the same ones), so ghosts and periodic images carry them as they carry any field.
inline constexpr const char* kDfsphFactorField = "dfsph.factor";
inline constexpr const char* kDfsphBoundaryDivergenceField = "dfsph.boundary_divergence";
inline constexpr const char* kDfsphAdvectedDensityField = "dfsph.advected_density";
inline constexpr const char* kDfsphStiffnessField = "dfsph.stiffness";
inline constexpr const char* kDfsphTotalStiffnessField = "dfsph.total_stiffness";
inline constexpr const char* kDfsphPredictedVelocityField = "dfsph.predicted_velocity";
inline constexpr const char* kDfsphPredictedPositionField = "dfsph.predicted_position";
inline constexpr const char* kDfsphSummedDensityField = "dfsph.summed_density";
inline constexpr const char* kDfsphBaseDensityField = "dfsph.base_density";

struct DfsphSettings {
  double eta, eta_divergence;
  int min_iterations, max_iterations, max_divergence_iterations;
  bool divergence, warm_start;
  double omega;
  bool stops_on_average;  // the constant-density solver's stopping error is the average
  // Checks the constant-density solve against densities summed at x + dt v* and iterates on
  // while they exceed eta (dfsph_summed_density.h); needs DfsphArrays' x_star, rho_star, rho_base.
  bool summed_density_check = false;
};

// The divergence-free solver leaves particles with fewer neighbours (fluid and boundary) alone:
// near the free surface the rate of change of the density is that of a particle losing or gaining
// neighbours, not a compression. 27 of the 33 an inner particle has at H = 2 s, not
// SPlisHSPlasH's 20: at 20 the surface layers pushed back on every inward motion of a free
// surface and stiffened a drop's oscillation by 10 % (measured in docs/surface-tension.md).
inline constexpr std::uint32_t kDfsphMinDivergenceNeighbours = 27;

struct ClearDfsphStiffnessStage {
  Real* k;
  Real* k_total;
  UPF_HD void operator()(std::uint32_t i) const {
    k[i] = 0;
    k_total[i] = 0;
  }
};

// The "non_pressure" part after the shared forces: the factors 1/D_i, the boundary particles'
// velocity divergence, v* = v.
template <class Executor>
void run_dfsph_non_pressure(const Executor& exec, const DfsphArrays& a) {
  exec.run(all_particles(a.n), ClearDfsphStiffnessStage{a.k, a.k_total});
  exec.run(a.owned, InverseDiagonalStage{a.f, a.fluid_gradient, a.boundary_gradient, a.factor});
  exec.run(a.owned, BoundaryVelocityDivergenceStage{a.f, a.boundary_divergence});
  exec.run(all_particles(a.n), CopyVelocityStage{a.f.v, a.v_star});
}

// The summed-density check's rounds at most: each sums the densities once more. Without a limit
// (rounds until max_iterations) the 2.5 cm dam break drove a particle to 100 m/s within 47 steps;
// 8 half re-bases did so at eta 2 % (step 48), 4 held at eta 1, 2 and 3 %.
inline constexpr int kDfsphSummedDensityRounds = 4;

// The stage that measures rho_adv and K: from the density, or from rho_base in a constant-density
// solve that checks summed densities.
inline DfsphStiffnessStage dfsph_measure(const DfsphArrays& a, const DfsphSettings& s, Real dt,
                                         bool divergence) {
  const bool rebased = !divergence && s.summed_density_check;
  return {a.f,
          a.fluid_gradient,
          a.boundary_gradient,
          a.boundary_divergence,
          rebased ? a.rho_base : a.density,
          a.factor,
          a.v_star,
          dt,
          Real(s.omega),
          divergence,
          kDfsphMinDivergenceNeighbours,
          a.rho_adv,
          a.k};
}

// The solve's iterations from `iteration` on: rho_adv and K measured, then accumulate, update and
// measure until the error is below eta. Returns {iterations, error}.
template <class Executor, class StoppingErrorOf>
std::pair<int, double> dfsph_iterate(const Executor& exec, const DfsphArrays& a,
                                     const DfsphSettings& s, Real dt, bool divergence,
                                     StoppingErrorOf&& stopping_error, int iteration) {
  Real* stiffness = divergence ? a.divergence_stiffness : a.density_stiffness;
  const double eta = divergence ? s.eta_divergence : s.eta;
  const int min_iterations = divergence ? 1 : s.min_iterations;
  const int max_iterations = divergence ? s.max_divergence_iterations : s.max_iterations;
  const Real dt_power = divergence ? dt : dt * dt;
  const DfsphVelocityStage update{a.f, a.fluid_gradient, a.boundary_gradient, a.k, dt, a.v_star};
  const DfsphStiffnessStage measure = dfsph_measure(a, s, dt, divergence);
  const DfsphAccumulateStage accumulate{a.k, dt_power, a.k_total, stiffness};
  exec.run(a.owned, measure);
  // An exact stopping error (a fixed-point sum for the average): the same iteration count for
  // any thread count and any backend. The divergence-free solver bounds the average, as the
  // paper does.
  const CompressionValue compression{a.f.rest_density, a.f.material, a.rho_adv};
  auto error_now = [&] {
    if (!divergence) return double(stopping_error(compression));
    return average_over(exec, a.owned, compression);
  };
  double error = error_now();
  while (iteration < max_iterations && (iteration < min_iterations || error > eta)) {
    exec.run(a.owned, accumulate);
    exec.run(a.owned, update);
    exec.run(a.owned, measure);
    error = error_now();
    ++iteration;
  }
  return {iteration, error};
}

// Corrects v* until the solve's error is below eta (the divergence-free solve when `divergence`,
// else the constant-density one); the error is stopping_error(value) over rho_adv's
// CompressionValue. Returns {iterations, error}.
template <class Executor, class StoppingErrorOf>
std::pair<int, double> dfsph_correct(const Executor& exec, const DfsphArrays& a,
                                     const DfsphSettings& s, Real dt, bool divergence,
                                     StoppingErrorOf&& stopping_error) {
  Real* stiffness = divergence ? a.divergence_stiffness : a.density_stiffness;
  const Real dt_power = divergence ? dt : dt * dt;
  const DfsphVelocityStage update{a.f, a.fluid_gradient, a.boundary_gradient, a.k, dt, a.v_star};
  const DfsphStiffnessStage measure = dfsph_measure(a, s, dt, divergence);
  if (s.warm_start) {
    exec.run(a.owned, measure);
    exec.run(a.owned, DfsphWarmStartStage{a.f, a.rho_adv, dt_power, stiffness, a.k, a.k_total});
    exec.run(a.owned, update);
  } else {
    exec.run(a.owned, ClearStiffnessStage{stiffness});
  }
  return dfsph_iterate(exec, a, s, dt, divergence, stopping_error, 0);
}

// The constant-density solve: v* += dt a_other, the correction, and the step's statistics.
template <class Executor, class StoppingErrorOf>
SolverStats dfsph_pressure_solve(const Executor& exec, const DfsphArrays& a, const DfsphSettings& s,
                                 Real dt, StoppingErrorOf&& stopping_error) {
  exec.run(a.owned, VelocityKickStage{a.other_acceleration, dt, a.v_star});
  if (s.summed_density_check) exec.run(a.owned, CopyScalarStage{a.density, a.rho_base});
  auto [iterations, error] = dfsph_correct(exec, a, s, dt, false, stopping_error);
  SolverStats stats;
  if (s.summed_density_check) {
    // Rounds of: rho* at x + dt v*, and while its error exceeds eta, the prediction re-based on
    // it and the iterations continued, within the same max_iterations.
    const CompressionValue summed{a.f.rest_density, a.f.material, a.rho_star};
    auto summed_error = [&] {
      exec.run(all_particles(a.n), PredictPositionStage{a.f.x, a.f.v, dt, a.x_star});
      exec.run(a.owned, PredictPositionStage{a.f.x, a.v_star, dt, a.x_star});
      exec.run(a.owned, SummedPredictedDensityStage{a.f, a.x_star, a.rho_star});
      return double(stopping_error(summed));
    };
    error = summed_error();
    for (int round = 0;
         round < kDfsphSummedDensityRounds && error > s.eta && iterations < s.max_iterations;
         ++round) {
      exec.run(a.owned,
               RebaseDensityStage{a.f, a.fluid_gradient, a.boundary_gradient, a.boundary_divergence,
                                  a.v_star, dt, a.rho_star, a.rho_base});
      iterations = dfsph_iterate(exec, a, s, dt, false, stopping_error, iterations).first;
      error = summed_error();
    }
    stats.iterations = iterations;
    stats.avg_density_error = s.stops_on_average ? error : average_over(exec, a.owned, summed);
    stats.max_density_error = double(exec.max_of(a.owned, summed));
    return stats;
  }
  const CompressionValue compression{a.f.rest_density, a.f.material, a.rho_adv};
  stats.iterations = iterations;
  stats.avg_density_error = s.stops_on_average ? error : average_over(exec, a.owned, compression);
  stats.max_density_error = double(exec.max_of(a.owned, compression));
  return stats;
}

// v = v*, x += dt v, and the exported pressure, after the reactions on bodies.
template <class Executor>
void run_dfsph_integration(const Executor& exec, const DfsphArrays& a, Real dt, Vec3* velocity,
                           Vec3* position, Real* pressure) {
  exec.run(a.owned,
           DfsphIntegrateStage{a.v_star, a.k_total, a.density, dt, velocity, position, pressure});
}

}  // namespace upf
