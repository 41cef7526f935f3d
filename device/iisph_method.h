// IISPH's pressure stage (Ihmsen et al. 2014) in the device pipeline (fluid_part.h): the
// diagonal and boundary divergence after the shared forces, then the relaxed Jacobi solve
// (iisph_solve.h, what IisphSolver runs) with the stopping error computed on the device
// (stopping_error.h). Its work arrays live here; the pressure field, the warm start of the next
// step, lives with the particles.
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
#include "solvers/iisph/iisph_solve.h"

namespace upf::device {

template <class Backend>
class IisphMethod : public ThreeStageMethod {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  using Setup = IisphSetup;
  explicit IisphMethod(IisphSetup setup)
      : setup_(std::move(setup)), stopping_(setup_.stop_percentile) {}

  void bind(DeviceParticles<Backend>& p) {
    inverse_diagonal_ = &p.scalar_array(kIisphInverseDiagonalField);
    boundary_divergence_ = &p.scalar_array(kIisphBoundaryDivergenceField);
    rho_adv_ = &p.scalar_array(kIisphAdvectedDensityField);
    predicted_ = &p.scalar_array(kIisphPredictedDensityField);
    next_ = &p.scalar_array(kIisphNextPressureField);
    v_adv_ = &p.vector_array(kIisphAdvectedVelocityField);
    if (setup_.solve.summed_density_check) {
      x_star_ = &p.vector_array(kIisphPredictedPositionField);
      rho_star_ = &p.scalar_array(kIisphSummedDensityField);
    }
  }

  template <class Executor, class Step>
  void non_pressure(const Executor& exec, const Step& s) {
    run_iisph_non_pressure(exec, arrays(s));
  }

  template <class Executor, class Step>
  SolverStats pressure(const Executor& exec, const Step& s) {
    return iisph_pressure_solve(
        exec, arrays(s), setup_.solve, s.dt,
        [&](const CompressionValue& value) { return stopping_(s.owned, value); });
  }

  // Reactions on bodies (IisphSolver's P_i = p_i / rho_i^2).
  template <class Executor, class Step>
  void add_reactions(const Executor& exec, const Step& s) const {
    run_boundary_reactions(exec, s.n, s.f, s.fluid_of_boundary, s.density, s.owns,
                           PressureOverDensitySquared{s.pressure, s.density, 1},
                           CubicSplineGradient{s.f.kernel}, s.boundary_force);
  }

  // The work arrays are the particles' scratch fields (DeviceParticles::bytes counts them).
  std::size_t bytes() const { return stopping_.bytes(); }

 private:
  template <class Step>
  IisphArrays arrays(const Step& s) {
    IisphArrays a{s.f,
                  s.owned,
                  s.n,
                  s.fluid_gradient,
                  s.boundary_gradient,
                  s.other_acceleration,
                  s.density,
                  s.pressure_acceleration,
                  s.pressure,
                  raw<Real>(*inverse_diagonal_),
                  raw<Real>(*boundary_divergence_),
                  raw<Real>(*rho_adv_),
                  raw<Real>(*predicted_),
                  raw<Real>(*next_),
                  raw<Vec3>(*v_adv_)};
    if (x_star_) {
      a.x_star = raw<Vec3>(*x_star_);
      a.rho_star = raw<Real>(*rho_star_);
    }
    return a;
  }

  IisphSetup setup_;
  DeviceStoppingError<Backend> stopping_;
  vector<Real>*inverse_diagonal_ = nullptr, *boundary_divergence_ = nullptr, *rho_adv_ = nullptr,
  *predicted_ = nullptr, *next_ = nullptr;
  vector<Vec3>* v_adv_ = nullptr;
  vector<Vec3>* x_star_ = nullptr;  // with the summed density check only
  vector<Real>* rho_star_ = nullptr;
};

}  // namespace upf::device
