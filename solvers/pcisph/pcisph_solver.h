// PCISPH: Solenthaler & Pajarola 2009, "Predictive-Corrective Incompressible SPH"
// (ACM TOG 28(3), SIGGRAPH 2009).
//
// Each step predicts velocities and positions under the current pressure forces, measures the
// predicted density error and raises pressures by delta * error until the average compression is
// below eta (at least min_iterations, at most max_iterations). delta is the paper's scaling factor
//   delta = -1 / (beta (-sum grad W . sum grad W - sum grad W . grad W)),  beta = 2 (dt m /
//   rho0)^2,
// with the sums over a full template neighbourhood on the initial lattice; it scales as 1/dt^2, so
// the template sum is taken once and delta follows every change of dt. Only compression is
// corrected: pressures stay >= 0. Past min_iterations the loop also ends, without correcting,
// when its error rises to divergence_factor times its smallest: at an impact with a large step
// the iteration can pump pressure instead of converging (pcisph_correction_loop.h). Boundaries
// follow Akinci et al. 2012 (shared with every fluid solver); non-pressure forces are gravity and
// the shared viscosity.
//
// The time step has a limit of its own besides the shared CFL: pressures start from zero every
// step, so liquid at rest stays compressed by what min_iterations corrections leave, measured
// as about kRestCompression g H (dt / s)^2 (3 iterations, cubic spline; H the liquid's height).
// Once that reaches eta, the stopping test flips between min_iterations and more from step to
// step, and the pressure, which grows with every iteration, flickers with it: a body floating at
// 1 cm spacing felt 0.4 to 305 N against its 28 N weight (docs/bodies.md). The limit keeps the
// resting compression at rest_compression * eta (Ihmsen et al. 2010 adapt the step to the density
// error for the same reason; this is its closed form at rest).
#pragma once

#include <vector>

#include "framework/params/param_binding.h"
#include "framework/solver/solver.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_solver_state.h"
#include "solvers/pcisph/pcisph_correction_loop.h"

namespace upf {

struct PcisphParams {
  double eta = 0;  // target average compression
  int min_iterations = 0, max_iterations = 0;
  double stop_percentile = 0;    // StoppingError: 0 the average
  double wall_pressure = 0;      // boundary_pressure.h: 1 on, 0 Akinci's term alone
  double rest_compression = 0;   // the resting compression the step allows, as a share of eta
  double divergence_factor = 0;  // pcisph_correction_loop.h; 0: the loop never stops for it
};

class PcisphSolver final : public Solver {
 public:
  PcisphSolver(const PcisphParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override { return "pcisph"; }
  void prepare(World& world) override;
  void initialize_fields(World& world) override { fluid_.initial_density(world); }
  Real max_time_step(const World& world) const override;
  std::vector<std::string> stages() const override;
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override { return fluid_.with_viscosity(stats_); }

  // What a device pipeline needs to run this solver's step on its own arrays (device/): the
  // correction loop's settings (pcisph_correction_loop.h) and the shared fluid state.
  PcisphLoopSettings loop_settings() const {
    return {eta_,         min_iterations_,   max_iterations_, stopping_.is_average(),
            delta_scale_, divergence_factor_};
  }
  double stop_percentile() const { return stopping_.percentile(); }
  std::string cannot_split() const override { return stopping_.cannot_split(); }
  const FluidSolverState& fluid_state() const { return fluid_; }
  static constexpr const char* kPredictedPosition = "pcisph.predicted_position";
  static constexpr const char* kPredictedDensity = "pcisph.predicted_density";
  // p / rho0^2, beside the pressure (pcisph_pressure_acceleration): a scratch field, so that ghosts
  // get it with the pressure.
  static constexpr const char* kScaledPressure = "pcisph.pressure_over_rest_density_squared";
  // Resting compression = kRestCompression g H (dt / s)^2, fitted to a 0.3 m deep tank at 1 and
  // 2 cm spacing and 1 to 3.3 ms steps (0.15 to 0.16; docs/bodies.md).
  static constexpr double kRestCompression = 0.16;

  static ParamBinding<PcisphParams> param_binding();
  // sum over the template neighbourhood of |grad W|^2 (the symmetric lattice makes sum grad W = 0
  // up to round-off, kept anyway as in the paper). delta = delta_scale / dt^2.
  static double template_delta_scale(Real spacing, const CubicSplineKernel& kernel);

 private:
  double eta_;
  double rest_compression_;
  StoppingError stopping_;
  int min_iterations_, max_iterations_;
  double divergence_factor_;
  std::vector<MaterialId> materials_;
  FluidSolverState fluid_;
  FieldHandle<Vec3> predicted_position_;
  FieldHandle<Real> predicted_density_;
  FieldHandle<Real> scaled_pressure_;
  double delta_scale_ = 0;    // delta = delta_scale_ / dt^2
  Real reference_speed_ = 0;  // sqrt(2 g H) of the initial liquid, for the CFL limit
  Real rest_time_step_ = 0;   // the resting-compression limit (0: none)
  SolverStats stats_;
  std::vector<Real> contrast_ratio_;  // per particle, with density contrast only
};

}  // namespace upf
