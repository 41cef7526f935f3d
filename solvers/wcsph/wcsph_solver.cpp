#include "solvers/wcsph/wcsph_solver.h"

#include "framework/world/world.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/fluid/sound_speed.h"
#include "solvers/wcsph/wcsph_kernels.h"

namespace upf {

std::vector<ParamSpec> WcsphSolver::param_specs() {
  return {
      {"sound_speed", "m/s", 0, 0, 1e4,
       "speed of sound c of the Tait equation; 0: 10 sqrt(2 g H), H the height of the "
       "initial liquid, for density variations of about 1 %"},
      {"alpha", "1", 0.1, 0, 10,
       "artificial viscosity constant (the paper uses 0.08 to 0.5); 0 leaves only the shared "
       "viscosity, so comparisons isolate the pressure solver"},
      {"cfl", "1", 0.4, 0.01, 1,
       "CFL number of dt <= cfl * spacing / (c + |v|max); it replaces time.cfl for WCSPH"},
  };
}

WcsphSolver::WcsphSolver(const ParamValues& params, std::vector<MaterialId> materials)
    : EquationOfStateSolver(std::move(materials)),
      requested_sound_speed_(Real(params.get("sound_speed"))),
      alpha_(Real(params.get("alpha"))),
      cfl_(Real(params.get("cfl"))) {}

void WcsphSolver::prepare_method(World& world) {
  sound_speed_ = requested_sound_speed_ > 0
                     ? requested_sound_speed_
                     : automatic_sound_speed(world, materials(), "sound_speed");
  tait_factor_.assign(world.materials().size(), 0);
  for (MaterialId m : materials())
    tait_factor_[m] = fluid().table.rest_density[m] * sound_speed_ * sound_speed_ / Real(7);
}

Real WcsphSolver::max_time_step(const World& world) const {
  return sound_speed_time_step(world, cfl_, sound_speed_, fluid().max_viscosity);
}

void WcsphSolver::add_own_non_pressure(const World& world, const FluidView& f, Real* density) {
  if (alpha_ <= 0) return;
  const Real h = Real(0.5) * world.settings().support_radius();  // the smoothing length
  const Real two_alpha_h_c = Real(2) * alpha_ * h * sound_speed_;
  const Vec3* gradient = fluid().fluid_gradient.data();
  Vec3* a_other = fluid().other_acceleration.data();
  fluid().owned.for_each(world.executor(), [&](std::uint32_t i) {
    a_other[i] += artificial_viscosity_acceleration(f, density, gradient, two_alpha_h_c, i);
  });
}

void WcsphSolver::compute_pressure(const World& world, const FluidView& f, const Real* density,
                                   Real* pressure) {
  const CpuExecutor& exec = world.executor();
  const Real* tait_factor = tait_factor_.data();
  const Vec3* gradient = fluid().fluid_gradient.data();
  const Vec3* boundary_gradient = fluid().boundary_gradient.data();
  Vec3* a_p = fluid().pressure_acceleration.data();
  fluid().owned.for_each(exec, [&](std::uint32_t i) {
    const MaterialId m = f.material[i];
    pressure[i] = tait_pressure(density[i], f.rest_density[m], tait_factor[m]);
  });
  fluid().owned.for_each(exec, [&](std::uint32_t i) {
    a_p[i] = wcsph_pressure_acceleration(f, density, pressure, gradient, boundary_gradient[i], i);
  });
}

}  // namespace upf
