// SPH's pressure stage (Müller et al. 2003) in the device pipeline (fluid_part.h): its own
// density and viscosity after the shared forces, then p = k (rho - rho0) and the pressure force
// (sph_steps.h, what SphSolver runs), and EquationOfStateSolver's statistics.
#pragma once

#include <utility>

#include "device/device_particles.h"
#include "device/fluid_setup.h"
#include "device/method_stages.h"
#include "device/state_equation_stats.h"
#include "solvers/sph/sph_steps.h"

namespace upf::device {

template <class Backend>
class SphMethod : public ThreeStageMethod {
 public:
  using Setup = SphSetup;
  explicit SphMethod(SphSetup setup) : setup_(std::move(setup)) {}

  void bind(DeviceParticles<Backend>&) {}

  template <class Executor, class Step>
  void non_pressure(const Executor& exec, const Step& s) const {
    run_sph_non_pressure(exec, s.owned, s.f, setup_.kernels, setup_.mu, s.density,
                         s.other_acceleration);
  }

  template <class Executor, class Step>
  SolverStats pressure(const Executor& exec, const Step& s) const {
    run_sph_pressure(exec, s.owned, s.f, setup_.kernels, setup_.stiffness, s.density, s.pressure,
                     s.pressure_acceleration);
    return state_equation_stats(exec, s);
  }

  template <class Executor, class Step>
  void add_reactions(const Executor& exec, const Step& s) const {
    run_sph_reactions(exec, s.n, s.f, s.fluid_of_boundary, setup_.kernels, s.density, s.pressure,
                      s.owns, s.boundary_force);
  }

  std::size_t bytes() const { return 0; }

 private:
  SphSetup setup_;
};

}  // namespace upf::device
