// DFSPH's stages (Bender & Koschier 2015, 2017) in the device pipeline (fluid_part.h): the
// shared step of dfsph_steps.h with the stopping error computed on the device (stopping_error.h).
// It has a fourth stage, "divergence", and its own integration (v = v*, x += dt v): the pipeline
// asks for both through kDivergenceStage and kOwnIntegration.
#pragma once

#include <cstddef>
#include <string>
#include <utility>

#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/fluid_setup.h"
#include "device/stopping_error.h"
#include "solvers/dfsph/dfsph_steps.h"
#include "solvers/fluid/boundary_reactions.h"

namespace upf::device {

template <class Backend>
class DfsphMethod {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  using Setup = DfsphSetup;
  static constexpr bool kDivergenceStage = true;
  static constexpr bool kOwnIntegration = true;

  explicit DfsphMethod(DfsphSetup setup)
      : setup_(std::move(setup)), stopping_(setup_.stop_percentile) {}

  void bind(DeviceParticles<Backend>& p) {
    density_stiffness_ = &p.scalar_array(setup_.density_stiffness);
    divergence_stiffness_ = &p.scalar_array(setup_.divergence_stiffness);
    factor_ = &p.scalar_array(kDfsphFactorField);
    boundary_divergence_ = &p.scalar_array(kDfsphBoundaryDivergenceField);
    rho_adv_ = &p.scalar_array(kDfsphAdvectedDensityField);
    k_ = &p.scalar_array(kDfsphStiffnessField);
    k_total_ = &p.scalar_array(kDfsphTotalStiffnessField);
    v_star_ = &p.vector_array(kDfsphPredictedVelocityField);
    if (setup_.solve.summed_density_check) {
      x_star_ = &p.vector_array(kDfsphPredictedPositionField);
      rho_star_ = &p.scalar_array(kDfsphSummedDensityField);
      rho_base_ = &p.scalar_array(kDfsphBaseDensityField);
    }
  }

  template <class Executor, class Step>
  void non_pressure(const Executor& exec, const Step& s) {
    run_dfsph_non_pressure(exec, arrays(s));
  }

  template <class Executor, class Step>
  void divergence(const Executor& exec, const Step& s) {
    if (!setup_.solve.divergence) return;
    dfsph_correct(exec, arrays(s), setup_.solve, s.dt, true, stopping_error(s));
  }

  template <class Executor, class Step>
  SolverStats pressure(const Executor& exec, const Step& s) {
    return dfsph_pressure_solve(exec, arrays(s), setup_.solve, s.dt, stopping_error(s));
  }

  // Reactions on bodies from the step's total K (DfsphSolver's P_i).
  template <class Executor, class Step>
  void add_reactions(const Executor& exec, const Step& s) const {
    run_boundary_reactions(exec, s.n, s.f, s.fluid_of_boundary, s.density, s.owns,
                           TotalStiffness{raw<Real>(*k_total_)}, CubicSplineGradient{s.f.kernel},
                           s.boundary_force);
  }

  template <class Executor, class Step>
  void integrate(const Executor& exec, const Step& s, Vec3* velocity, Vec3* position) {
    run_dfsph_integration(exec, arrays(s), s.dt, velocity, position, s.pressure);
  }

  // The work arrays are the particles' scratch fields (DeviceParticles::bytes counts them).
  std::size_t bytes() const { return stopping_.bytes(); }

 private:
  template <class Step>
  auto stopping_error(const Step& s) {
    return
        [this, owned = s.owned](const CompressionValue& value) { return stopping_(owned, value); };
  }

  template <class Step>
  DfsphArrays arrays(const Step& s) {
    DfsphArrays a{s.f,
                  s.owned,
                  s.n,
                  s.fluid_gradient,
                  s.boundary_gradient,
                  s.other_acceleration,
                  s.density,
                  raw<Real>(*density_stiffness_),
                  raw<Real>(*divergence_stiffness_),
                  raw<Real>(*factor_),
                  raw<Real>(*boundary_divergence_),
                  raw<Real>(*rho_adv_),
                  raw<Real>(*k_),
                  raw<Real>(*k_total_),
                  raw<Vec3>(*v_star_)};
    if (x_star_) {
      a.x_star = raw<Vec3>(*x_star_);
      a.rho_star = raw<Real>(*rho_star_);
      a.rho_base = raw<Real>(*rho_base_);
    }
    return a;
  }

  DfsphSetup setup_;
  DeviceStoppingError<Backend> stopping_;
  vector<Real>*factor_ = nullptr, *boundary_divergence_ = nullptr, *rho_adv_ = nullptr,
  *k_ = nullptr, *k_total_ = nullptr;
  vector<Vec3>* v_star_ = nullptr;
  vector<Vec3>* x_star_ = nullptr;  // with the summed density check only
  vector<Real>*rho_star_ = nullptr, *rho_base_ = nullptr;
  vector<Real>* density_stiffness_ = nullptr;
  vector<Real>* divergence_stiffness_ = nullptr;
};

}  // namespace upf::device
