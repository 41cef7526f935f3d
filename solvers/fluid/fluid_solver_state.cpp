#include "solvers/fluid/fluid_solver_state.h"

#include <algorithm>

#include "framework/world/world.h"
#include "solvers/fluid/fluid_forces.h"

namespace upf {

void FluidSolverState::prepare(World& world, const std::vector<MaterialId>& materials) {
  Particles& p = world.particles();
  p.scalar_field("density", 0, true);
  p.scalar_field("pressure", 0, true);
  lists.request(world);
  // Reactions are gathered from the rigid side: for each rigid particle, its liquid neighbours.
  if (world.coupling().active(CouplingArray::BoundaryForce) && p.count(ParticleType::Rigid) > 0)
    reaction_list = world.request_neighbours(mask_of(ParticleType::Rigid), kLiquidMask);
  table.load(world);
  owned.set_materials(world.materials().size(), materials);
  max_viscosity = 0;
  for (MaterialId m : materials) max_viscosity = std::max(max_viscosity, table.viscosity[m]);
}

FluidView FluidSolverState::begin_step(const World& world) {
  const std::size_t n = world.particles().size();
  owned.rebuild(world.particles());
  fluid_gradient.resize(world.neighbours(lists.fluid).total());
  boundary_gradient.resize(n);
  other_acceleration.resize(n);
  pressure_acceleration.resize(n);
  return make_fluid_view(world, table, lists);
}

void FluidSolverState::shared_forces(const World& world, const FluidView& f, Real* density) {
  const CpuExecutor& exec = world.executor();
  const Vec3 g = world.settings().gravity;
  Vec3* gradient = fluid_gradient.data();
  Vec3* boundary = boundary_gradient.data();
  Vec3* a_other = other_acceleration.data();
  owned.for_each(exec, [&](std::uint32_t i) {
    density[i] = density_and_gradients(f, gradient, boundary[i], i);
  });
  owned.for_each(exec, [&](std::uint32_t i) {
    a_other[i] = g + viscosity_acceleration(f, density, gradient, i);
  });
  if (world.coupling().active(CouplingArray::LiquidForce)) {
    const Vec3* force = world.coupling()[CouplingArray::LiquidForce].data();
    owned.for_each(exec, [&](std::uint32_t i) { a_other[i] += force[i] / f.mass[i]; });
  }
}

void FluidSolverState::predict_unowned(const World& world, const FluidView& f, Vec3* x_star,
                                       Real dt) const {
  world.executor().for_each(world.particles().size(), [&](std::size_t i) {
    if (f.type[i] != ParticleType::Liquid || !owned.owns(f.material[i]))
      x_star[i] = f.x[i] + f.v[i] * dt;
  });
}

void FluidSolverState::integrate(World& world, Real dt) const {
  Particles& p = world.particles();
  Vec3* v = p.velocity.data();
  Vec3* x = p.position.data();
  const Vec3* a_other = other_acceleration.data();
  const Vec3* a_p = pressure_acceleration.data();
  owned.for_each(world.executor(), [&](std::uint32_t i) {
    v[i] += (a_other[i] + a_p[i]) * dt;
    x[i] += v[i] * dt;
  });
}

}  // namespace upf
