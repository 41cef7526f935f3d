// PCISPH's predict-correct loop (Solenthaler & Pajarola 2009), written once for every executor:
// PcisphSolver runs it on the CPU executor, the device pipeline on its backends (device/). It
// takes plain views and an executor with run / fixed_point_sum / max_of, so the same statements
// give the same bits wherever they run. C++17: nvcc builds it too.
#pragma once

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
};

struct PcisphLoopSettings {
  double eta;
  int min_iterations, max_iterations;
  bool stops_on_average;  // the stopping error is the average compression (stop_percentile 0)
  double delta_scale;     // delta = delta_scale / dt^2
};

// Predict, correct and accelerate until the stopping error (stopping_error(value): a double from
// the owned particles' CompressionValue) is at most eta after at least min_iterations, at most
// max_iterations times. Positions of the particles the solver does not move must already be
// predicted in x_star. Returns the iterations and the average and largest compression.
template <class Executor, class StoppingErrorOf>
SolverStats pcisph_correction_loop(const Executor& exec, const PcisphLoopArrays& a,
                                   const PcisphLoopSettings& s, Real dt,
                                   StoppingErrorOf&& stopping_error) {
  const Real delta = Real(s.delta_scale / (double(dt) * double(dt)));
  const PcisphPredictStage predict{a.f, a.other_acceleration, a.pressure_acceleration, dt,
                                   a.x_star};
  const PcisphCorrectPressureStage correct{a.f, a.x_star, delta, a.rho_star, a.pressure};
  const PcisphPressureAccelerationStage accelerate{a.f, a.pressure, a.fluid_gradient,
                                                   a.boundary_gradient, a.pressure_acceleration};
  const CompressionValue compression{a.f.rest_density, a.f.material, a.rho_star};
  double error = 0;
  int iteration = 0;
  while (iteration < s.max_iterations) {
    exec.run(a.owned, predict);
    exec.run(a.owned, correct);
    // An exact stopping error (a fixed-point sum for the average): the same iteration count
    // for any thread count and any backend.
    error = stopping_error(compression);
    exec.run(a.owned, accelerate);
    ++iteration;
    if (iteration >= s.min_iterations && error <= s.eta) break;
  }
  SolverStats stats;
  stats.iterations = iteration;
  stats.avg_density_error = s.stops_on_average ? error : average_over(exec, a.owned, compression);
  stats.max_density_error = double(exec.max_of(a.owned, compression));
  return stats;
}

}  // namespace upf
