#include "solvers/sph/sph_solver.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "framework/world/world.h"
#include "solvers/fluid/fluid_time_step.h"
#include "solvers/fluid/lattice_template.h"
#include "solvers/fluid/sound_speed.h"
#include "solvers/sph/sph_kernel_sets.h"
#include "solvers/sph/sph_kernels.h"
#include "solvers/sph/sph_steps.h"

namespace upf {

ParamBinding<SphParams> SphSolver::param_binding() {
  ParamBinding<SphParams> b;
  b.add({"stiffness", "m^2/s^2", 0, 0, 1e7,
         "k in p = k (rho - rho0), the step obeys CFL on sqrt(k); 0: 2 c^2 with c = 10 "
         "sqrt(2 g H), H the height of the initial liquid: WCSPH's automatic speed of sound, "
         "doubled in k since the paper's pressure force is half the pressure gradient (density "
         "varies about 1 %)"},
        &SphParams::stiffness);
  b.add({"viscosity", "Pa s", 0, 0, 1e4,
         "dynamic viscosity mu of the paper's viscosity force, added to the material's shared "
         "viscosity (0: only the shared one, so comparisons isolate the pressure solver)"},
        &SphParams::viscosity);
  b.add({"cubic_spline", "1", 1, 0, 1,
         "1: the cubic spline for density, pressure and viscosity; 0: the paper's kernels "
         "(poly6, spiky, viscosity), which need viscosity of about 20 Pa s to stay stable"},
        &SphParams::cubic_spline);
  return b;
}

SphSolver::SphSolver(const SphParams& params, std::vector<MaterialId> materials)
    : EquationOfStateSolver(std::move(materials)),
      requested_stiffness_(Real(params.stiffness)),
      mu_(Real(params.viscosity)),
      cubic_spline_(params.cubic_spline) {}

Real SphSolver::poly6_lattice_scale(Real spacing, Real support_radius) {
  const MullerKernels w(support_radius);
  double sum = 0;
  for_each_lattice_offset(spacing, support_radius,
                          [&](const Vec3& r) { sum += double(w.poly6(norm(r))); });
  const double volume = double(spacing) * spacing * spacing;
  return Real(1.0 / (volume * sum));
}

void SphSolver::prepare_method(World& world) {
  if (requested_stiffness_ > 0) {
    stiffness_ = requested_stiffness_;
  } else {
    const Real c = automatic_sound_speed(world, materials(), "stiffness");
    stiffness_ = Real(2) * c * c;
  }
  const auto& s = world.settings();
  poly6_scale_ = poly6_lattice_scale(s.spacing, s.support_radius());
  const FluidMaterialTable& table = fluid().table;
  max_viscosity_ = 0;
  for (MaterialId m : materials())
    max_viscosity_ = std::max(max_viscosity_, table.viscosity[m] + mu_ / table.rest_density[m]);
}

Real SphSolver::max_time_step(const World& world) const {
  return sound_speed_time_step(world, Real(world.settings().time.cfl), std::sqrt(stiffness_),
                               {max_viscosity_, fluid().table.max_sigma_over_density});
}

SphKernelChoice SphSolver::kernel_choice(Real support_radius) const {
  return {cubic_spline_, support_radius, poly6_scale_};
}

void SphSolver::add_own_non_pressure(const World& world, const FluidView& f, Real* density) {
  run_sph_non_pressure(world.executor(), fluid().owned.range(), f,
                       kernel_choice(world.settings().support_radius()), mu_, density,
                       fluid().other_acceleration.data());
}

void SphSolver::compute_pressure(const World& world, const FluidView& f, const Real* density,
                                 Real* pressure) {
  run_sph_pressure(world.executor(), fluid().owned.range(), f,
                   kernel_choice(world.settings().support_radius()), stiffness_, density, pressure,
                   fluid().pressure_acceleration);
}

void SphSolver::add_reactions(World& world, const FluidView& f, const Real* density,
                              const Real* pressure) const {
  const FluidSolverState& state = fluid();
  if (state.reaction_list < 0) return;
  std::vector<Vec3>& force = world.coupling()[CouplingArray::BoundaryForce];
  run_sph_reactions(world.executor(), force.size(), f,
                    view_of(world.neighbours(state.reaction_list)),
                    kernel_choice(world.settings().support_radius()), density, pressure,
                    state.owned.materials(), force.data());
}

}  // namespace upf
