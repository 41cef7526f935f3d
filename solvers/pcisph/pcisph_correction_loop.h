// PCISPH's predict-correct loop (Solenthaler & Pajarola 2009), written once for every executor:
// PcisphSolver runs it on the CPU executor, the device pipeline on its backends (device/). It
// takes plain views and an executor with run / fixed_point_sum / max_of, so the same statements
// give the same bits wherever they run. C++17: nvcc builds it too.
#pragma once

#include <limits>

#include "framework/executors/average_over.h"
#include "framework/executors/particle_range.h"
#include "framework/solver/solver.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/pcisph/pcisph_kernels.h"

namespace upf {

struct PcisphLoopArrays {
  FluidView f;
  ParticleRange owned;
  const Vec3* other_acceleration;
  FluidGradients fluid_gradient;
  const Vec3* boundary_gradient;
  Vec3* pressure_acceleration;
  Vec3* x_star;
  Real* rho_star;
  Real* pressure;
  // p / rho0^2 per particle, written with p by each correction (every liquid neighbour is owned
  // by this solver or a ghost of it: the scene reader refuses liquids of two solvers).
  Real* scaled_pressure;
  Real* contrast_ratio;  // per particle with density contrast (f.density_contrast), else null
};

struct PcisphLoopSettings {
  double eta;
  int min_iterations, max_iterations;
  bool stops_on_average;     // the stopping error is the average compression (stop_percentile 0)
  double delta_scale;        // delta = delta_scale / dt^2
  double divergence_factor;  // stop once the error exceeds this times its smallest; 0: never
};

// Predict, test, correct: the positions x* that the current pressures lead to, the densities
// there, the stopping error (stopping_error(value): a double from the owned particles'
// CompressionValue), then p += delta (rho* - rho0) and the pressure accelerations. The loop ends
// after the correction of the first prediction whose error is at most eta, once at least
// min_iterations corrections are done, or after max_iterations corrections (the paper's loop).
// It also ends, without correcting, when past min_iterations the error exceeds
// divergence_factor times its smallest value so far: an iteration that pumps pressure instead of
// converging (at an impact, with a large step; docs/solvers.md). A correction there would kick
// the particles with the pumped pressure; without it they land at x*, where the reported errors
// were measured. Each correction's acceleration pass but the last also makes the next
// prediction. Positions of the particles the solver does not move must already be predicted in
// x_star. Returns the corrections and the average and largest compression of the last prediction.
template <class Executor, class StoppingErrorOf>
SolverStats pcisph_correction_loop(const Executor& exec, const PcisphLoopArrays& a,
                                   const PcisphLoopSettings& s, Real dt,
                                   StoppingErrorOf&& stopping_error) {
  const Real delta = Real(s.delta_scale / (double(dt) * double(dt)));
  const PcisphPredictStage predict{a.f, a.other_acceleration, a.pressure_acceleration, dt,
                                   a.x_star};
  const PcisphPredictedDensityStage density{a.f, a.x_star, a.rho_star, a.contrast_ratio};
  const PcisphCorrectPressureStage correct{a.f,   a.rho_star, a.contrast_ratio,
                                           delta, a.pressure, a.scaled_pressure};
  const PcisphPressureAccelerationStage accelerate{a.f,
                                                   a.pressure,
                                                   a.scaled_pressure,
                                                   a.fluid_gradient,
                                                   a.boundary_gradient,
                                                   a.pressure_acceleration};
  const PcisphAccelerateAndPredictStage accelerate_and_predict{accelerate, predict};
  const CompressionValue compression{a.f.rest_density, a.f.material, a.rho_star};
  double error = 0, smallest = std::numeric_limits<double>::infinity();
  int corrections = 0;
  exec.run(a.owned, predict);
  while (corrections < s.max_iterations) {
    // rho* is read by its own particle only (the correction's refresh sends it with p).
    exec.run_unshared(a.owned, density);
    // An exact stopping error (a fixed-point sum for the average): the same iteration count
    // for any thread count and any backend.
    error = stopping_error(compression);
    if (s.divergence_factor > 0 && corrections > s.min_iterations &&
        error > s.divergence_factor * smallest)
      break;
    smallest = error < smallest ? error : smallest;
    exec.run(a.owned, correct);
    ++corrections;
    // The last correction's acceleration needs no prediction after it.
    if ((corrections >= s.min_iterations && error <= s.eta) || corrections == s.max_iterations) {
      exec.run(a.owned, accelerate);
      break;
    }
    exec.run(a.owned, accelerate_and_predict);
  }
  SolverStats stats;
  stats.iterations = corrections;
  stats.avg_density_error = s.stops_on_average ? error : average_over(exec, a.owned, compression);
  stats.max_density_error = double(exec.max_of(a.owned, compression));
  return stats;
}

}  // namespace upf
