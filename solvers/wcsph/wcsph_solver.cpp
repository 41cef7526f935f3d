#include "solvers/wcsph/wcsph_solver.h"

#include "framework/world/world.h"
#include "solvers/fluid/compression_stats.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/fluid/sound_speed.h"
#include "solvers/wcsph/wcsph_steps.h"

namespace upf {

ParamBinding<WcsphParams> WcsphSolver::param_binding() {
  ParamBinding<WcsphParams> b;
  b.add({"sound_speed", "m/s", 0, 0, 1e4,
         "speed of sound c of the Tait equation; 0: 10 sqrt(2 g H), H the height of the "
         "initial liquid, for density variations of about 1 %"},
        &WcsphParams::sound_speed);
  b.add({"alpha", "1", 0.1, 0, 10,
         "artificial viscosity constant (the paper uses 0.08 to 0.5); 0 leaves only the shared "
         "viscosity, so comparisons isolate the pressure solver"},
        &WcsphParams::alpha);
  b.add({"cfl", "1", 0.4, 0.01, 1,
         "CFL number of dt <= cfl * spacing / (c + |v|max); it replaces time.cfl for WCSPH"},
        &WcsphParams::cfl);
  b.add(wall_pressure_spec(), &WcsphParams::wall_pressure);
  return b;
}

WcsphSolver::WcsphSolver(const WcsphParams& params, std::vector<MaterialId> materials)
    : EquationOfStateSolver(std::move(materials)),
      requested_sound_speed_(Real(params.sound_speed)),
      alpha_(Real(params.alpha)),
      cfl_(Real(params.cfl)) {
  set_wall_pressure(params.wall_pressure != 0);
}

void WcsphSolver::prepare_method(World& world) {
  sound_speed_ = requested_sound_speed_ > 0
                     ? requested_sound_speed_
                     : automatic_sound_speed(world, materials(), "sound_speed");
  tait_factor_.assign(world.materials().size(), 0);
  for (MaterialId m : materials())
    tait_factor_[m] = fluid().table.rest_density[m] * sound_speed_ * sound_speed_ / Real(7);
}

Real WcsphSolver::max_time_step(const World& world) const {
  return sound_speed_time_step(world, cfl_, sound_speed_, fluid().force_limits());
}

Real WcsphSolver::artificial_viscosity_factor(Real support_radius) const {
  if (alpha_ <= 0) return 0;
  const Real h = Real(0.5) * support_radius;  // the smoothing length
  return Real(2) * alpha_ * h * sound_speed_;
}

void WcsphSolver::add_own_non_pressure(const World& world, const FluidView& f, Real* density) {
  run_wcsph_viscosity(world.executor(), fluid().owned.range(), f, density,
                      fluid().fluid_gradient.data(),
                      artificial_viscosity_factor(world.settings().support_radius()),
                      fluid().other_acceleration.data());
}

void WcsphSolver::compute_pressure(const World& world, const FluidView& f, const Real* density,
                                   Real* pressure) {
  run_wcsph_pressure(world.executor(), fluid().owned.range(), f, density, tait_factor_.data(),
                     pressure, fluid().fluid_gradient.data(), fluid().boundary_gradient.data(),
                     fluid().pressure_acceleration);
}

}  // namespace upf
