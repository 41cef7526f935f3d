// IISPH's step (Ihmsen et al. 2014) after the shared forces, written once for every executor:
// IisphSolver runs it on the CPU executor, the device pipeline on its backends (device/). Plain
// views and an executor with run / fixed_point_sum / max_of, so the same statements give the
// same bits wherever they run. C++17: nvcc builds it too.
#pragma once

#include <cstddef>
#include <utility>

#include "framework/executors/average_over.h"
#include "framework/executors/particle_range.h"
#include "framework/solver/solver.h"
#include "solvers/fluid/density_rate.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/fluid/summed_density.h"
#include "solvers/iisph/iisph_kernels.h"

namespace upf {

struct IisphArrays {
  FluidView f;
  ParticleRange owned;
  std::size_t n;  // all particles
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  const Vec3* other_acceleration;
  const Real* density;
  Vec3* pressure_acceleration;
  Real* pressure;  // the field: last step's pressures in, this step's out
  // Per-step work arrays over all particles.
  Real* inverse_diagonal;
  Real* boundary_divergence;
  Real* rho_adv;
  Real* predicted;
  Real* next;
  Vec3* v_adv;
  // With IisphSettings::summed_density_check (else null): the predicted positions and the
  // densities summed there.
  Vec3* x_star = nullptr;
  Real* rho_star = nullptr;
};

// The scratch fields that hold the work arrays (IisphSolver declares them; the device pipeline
// binds the same ones), so ghosts and periodic images carry them as they carry any field.
inline constexpr const char* kIisphInverseDiagonalField = "iisph.inverse_diagonal";
inline constexpr const char* kIisphBoundaryDivergenceField = "iisph.boundary_divergence";
inline constexpr const char* kIisphAdvectedDensityField = "iisph.advected_density";
inline constexpr const char* kIisphPredictedDensityField = "iisph.predicted_density";
inline constexpr const char* kIisphNextPressureField = "iisph.next_pressure";
inline constexpr const char* kIisphAdvectedVelocityField = "iisph.advected_velocity";
inline constexpr const char* kIisphPredictedPositionField = "iisph.predicted_position";
inline constexpr const char* kIisphSummedDensityField = "iisph.summed_density";

// The summed-density check's rounds at most (each sums the densities once more), as DFSPH's.
inline constexpr int kIisphSummedDensityRounds = 4;

struct IisphSettings {
  double eta;
  int min_iterations, max_iterations;
  double omega;           // relaxation of the Jacobi update
  bool stops_on_average;  // the stopping error is the average compression (stop_percentile 0)
  // Once converged, checks the solve against densities summed at x + dt v and iterates on while
  // their error exceeds eta (dfsph_summed_density.h explains why a linear prediction needs it).
  bool summed_density_check = false;
};

// Zeroes a vector per particle.
struct ClearVectorStage {
  Vec3* v;
  UPF_HD void operator()(std::uint32_t i) const { v[i] = Vec3{}; }
};

// The "non_pressure" part after the shared forces: no pressure acceleration yet, the diagonal
// of the pressure system and the boundary particles' velocity divergence.
template <class Executor>
void run_iisph_non_pressure(const Executor& exec, const IisphArrays& a) {
  exec.run(all_particles(a.n), ClearVectorStage{a.pressure_acceleration});
  exec.run(a.owned,
           InverseDiagonalStage{a.f, a.fluid_gradient, a.boundary_gradient, a.inverse_diagonal});
  exec.run(a.owned, BoundaryVelocityDivergenceStage{a.f, a.boundary_divergence});
}

// Relaxed Jacobi iterations from `iteration` on, from the pressures in a.pressure (every
// particle's, in both buffers), until the stopping error (stopping_error(value) over the
// predicted densities' CompressionValue) is at most eta after min_iterations, at most
// max_iterations in all; the final pressures end in a.pressure with their acceleration.
// Returns {iterations, error}.
template <class Executor, class StoppingErrorOf>
std::pair<int, double> iisph_iterate(const Executor& exec, const IisphArrays& a,
                                     const IisphSettings& s, Real dt,
                                     StoppingErrorOf&& stopping_error, int iteration) {
  Real* current = a.pressure;
  Real* next = a.next;
  const CompressionValue compression{a.f.rest_density, a.f.material, a.predicted};
  double error = 0;
  while (iteration < s.max_iterations) {
    exec.run(a.owned, IisphPressureAccelerationStage{a.f, a.fluid_gradient, a.boundary_gradient,
                                                     a.density, current, a.pressure_acceleration});
    exec.run(a.owned,
             IisphPressureUpdateStage{a.f, a.fluid_gradient, a.boundary_gradient, a.density,
                                      a.inverse_diagonal, a.rho_adv, a.pressure_acceleration,
                                      current, dt, Real(s.omega), a.predicted, next});
    // An exact stopping error (a fixed-point sum for the average): the same iteration count
    // for any thread count and any backend.
    error = stopping_error(compression);
    std::swap(current, next);
    ++iteration;
    if (iteration >= s.min_iterations && error <= s.eta) break;
  }
  if (current != a.pressure) exec.run(a.owned, CopyScalarStage{current, a.pressure});
  exec.run(a.owned, IisphPressureAccelerationStage{a.f, a.fluid_gradient, a.boundary_gradient,
                                                   a.density, a.pressure, a.pressure_acceleration});
  return {iteration, error};
}

// The pressure solve: advected velocities and densities, the warm start (half the last
// pressures), the iterations (iisph_iterate), and with summed_density_check rounds of: rho* at
// x + dt v, and while its stopping error exceeds eta, rho_adv re-based on it and the iterations
// continued, within the same max_iterations.
template <class Executor, class StoppingErrorOf>
SolverStats iisph_pressure_solve(const Executor& exec, const IisphArrays& a, const IisphSettings& s,
                                 Real dt, StoppingErrorOf&& stopping_error) {
  exec.run(all_particles(a.n), CopyVelocityStage{a.f.v, a.v_adv});
  exec.run(a.owned, VelocityKickStage{a.other_acceleration, dt, a.v_adv});
  exec.run(a.owned,
           IisphAdvectedDensityStage{a.f, a.fluid_gradient, a.boundary_gradient,
                                     a.boundary_divergence, a.density, a.v_adv, dt, a.rho_adv});
  exec.run(a.owned, HalvePressureStage{a.pressure});
  // Particles not owned keep their pressure in both buffers.
  exec.run(all_particles(a.n), CopyScalarStage{a.pressure, a.next});
  auto [iterations, error] = iisph_iterate(exec, a, s, dt, stopping_error, 0);
  SolverStats stats;
  const CompressionValue summed{a.f.rest_density, a.f.material, a.rho_star};
  if (s.summed_density_check) {
    auto summed_error = [&] {
      exec.run(all_particles(a.n), PredictPositionStage{a.f.x, a.f.v, dt, a.x_star});
      exec.run(a.owned,
               IisphPredictPositionStage{a.f.x, a.v_adv, a.pressure_acceleration, dt, a.x_star});
      exec.run(a.owned, SummedPredictedDensityStage{a.f, a.x_star, a.rho_star});
      return double(stopping_error(summed));
    };
    error = summed_error();
    for (int round = 0;
         round < kIisphSummedDensityRounds && error > s.eta && iterations < s.max_iterations;
         ++round) {
      // The linear prediction at the final pressures into `predicted` (the Jacobi update it
      // also writes to `next` is dropped: both buffers take the final pressures again).
      exec.run(a.owned,
               IisphPressureUpdateStage{a.f, a.fluid_gradient, a.boundary_gradient, a.density,
                                        a.inverse_diagonal, a.rho_adv, a.pressure_acceleration,
                                        a.pressure, dt, Real(s.omega), a.predicted, a.next});
      exec.run(a.owned, IisphRebaseStage{a.rho_star, a.predicted, a.rho_adv});
      exec.run(all_particles(a.n), CopyScalarStage{a.pressure, a.next});
      iterations = iisph_iterate(exec, a, s, dt, stopping_error, iterations).first;
      error = summed_error();
    }
  }
  const CompressionValue compression =
      s.summed_density_check ? summed
                             : CompressionValue{a.f.rest_density, a.f.material, a.predicted};
  stats.iterations = iterations;
  stats.avg_density_error = s.stops_on_average ? error : average_over(exec, a.owned, compression);
  stats.max_density_error = double(exec.max_of(a.owned, compression));
  return stats;
}

}  // namespace upf
