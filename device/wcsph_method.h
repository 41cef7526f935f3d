// WCSPH's pressure stage (Becker & Teschner 2007) in the device pipeline (fluid_part.h): the
// artificial viscosity after the shared forces, then Tait pressures and pressure accelerations
// (wcsph_steps.h, what WcsphSolver runs), and EquationOfStateSolver's statistics.
#pragma once

#include <cstddef>
#include <utility>

#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/fluid_setup.h"
#include "device/method_stages.h"
#include "device/state_equation_stats.h"
#include "solvers/fluid/boundary_reactions.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/wcsph/wcsph_steps.h"

namespace upf::device {

template <class Backend>
class WcsphMethod : public ThreeStageMethod {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  using Setup = WcsphSetup;
  explicit WcsphMethod(WcsphSetup setup)
      : setup_(std::move(setup)),
        tait_factor_(setup_.tait_factor.begin(), setup_.tait_factor.end()) {}

  void bind(DeviceParticles<Backend>&) {}

  template <class Executor, class Step>
  void non_pressure(const Executor& exec, const Step& s) const {
    run_wcsph_viscosity(exec, s.owned, s.f, s.density, s.fluid_gradient,
                        setup_.artificial_viscosity, s.other_acceleration);
  }

  // One state-equation evaluation; the density error statistics of compression_stats.h.
  template <class Executor, class Step>
  SolverStats pressure(const Executor& exec, const Step& s) const {
    run_wcsph_pressure(exec, s.owned, s.f, s.density, raw<Real>(tait_factor_), s.pressure,
                       s.fluid_gradient, s.boundary_gradient, s.pressure_acceleration);
    return state_equation_stats(exec, s);
  }

  // Reactions on bodies (EquationOfStateSolver's P_i = p_i / rho_i^2).
  template <class Executor, class Step>
  void add_reactions(const Executor& exec, const Step& s) const {
    run_boundary_reactions(exec, s.n, s.f, s.fluid_of_boundary, s.density, s.owns,
                           PressureOverDensitySquared{s.pressure, s.density, Real(1)},
                           CubicSplineGradient{s.f.kernel}, s.boundary_force);
  }

  std::size_t bytes() const { return bytes_of(tait_factor_); }

 private:
  WcsphSetup setup_;
  vector<Real> tait_factor_;
};

}  // namespace upf::device
