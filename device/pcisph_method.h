// PCISPH's pressure stage (Solenthaler & Pajarola 2009) in the device pipeline (fluid_part.h):
// the positions of the particles it does not move predicted once, then the shared correction loop
// (pcisph_correction_loop.h) with the stopping error computed on the device (stopping_error.h).
#pragma once

#include <cstddef>
#include <utility>

#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/fluid_setup.h"
#include "device/method_stages.h"
#include "device/stopping_error.h"
#include "solvers/fluid/boundary_reactions.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/pcisph/pcisph_correction_loop.h"

namespace upf::device {

template <class Backend>
class PcisphMethod : public ThreeStageMethod {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  using Setup = PcisphSetup;
  explicit PcisphMethod(PcisphSetup setup)
      : setup_(std::move(setup)), stopping_(setup_.stop_percentile) {}

  void bind(DeviceParticles<Backend>& p) {
    rho_star_ = &p.scalar_array(setup_.predicted_density);
    x_star_ = &p.vector_array(setup_.predicted_position);
    scaled_pressure_ = &p.scalar_array(setup_.scaled_pressure);
  }

  template <class Executor, class Step>
  void non_pressure(const Executor& exec, const Step& s) const {
    exec.run(s.owned, ClearPressureStage{s.pressure, s.pressure_acceleration});
  }

  template <class Executor, class Step>
  SolverStats pressure(const Executor& exec, const Step& s) {
    Vec3* x_star = raw<Vec3>(*x_star_);
    Real* rho_star = raw<Real>(*rho_star_);
    exec.run(all_particles(s.n), PredictUnownedStage{s.f, s.owns, s.dt, x_star});
    PcisphLoopArrays arrays{s.f,
                            s.owned,
                            s.other_acceleration,
                            s.fluid_gradient,
                            s.boundary_gradient,
                            s.pressure_acceleration,
                            x_star,
                            rho_star,
                            s.pressure,
                            raw<Real>(*scaled_pressure_),
                            nullptr};
    if (s.f.density_contrast) {
      contrast_ratio_.resize(s.n);
      arrays.contrast_ratio = raw<Real>(contrast_ratio_);
    }
    return pcisph_correction_loop(
        exec, arrays, setup_.loop, s.dt,
        [&](const CompressionValue& value) { return stopping_(s.owned, value); });
  }

  // Reactions on bodies from the final pressures (PcisphSolver's P_i = p_i / rho0_i^2).
  template <class Executor, class Step>
  void add_reactions(const Executor& exec, const Step& s) const {
    run_boundary_reactions(
        exec, s.n, s.f, s.fluid_of_boundary, s.density, s.owns,
        PressureOverRestDensitySquared{s.pressure, s.f.rest_density, s.f.material},
        CubicSplineGradient{s.f.kernel}, s.boundary_force);
  }

  std::size_t bytes() const { return stopping_.bytes() + contrast_ratio_.size() * sizeof(Real); }

 private:
  PcisphSetup setup_;
  DeviceStoppingError<Backend> stopping_;
  vector<Real>* rho_star_ = nullptr;
  vector<Vec3>* x_star_ = nullptr;
  vector<Real>* scaled_pressure_ = nullptr;
  vector<Real> contrast_ratio_;  // with density contrast only
};

}  // namespace upf::device
