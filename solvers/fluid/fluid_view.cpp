#include "solvers/fluid/fluid_view.h"

#include "framework/world/world.h"

namespace upf {

void FluidMaterialTable::load(const World& world) {
  const auto& mats = world.materials().all();
  rest_density.assign(mats.size(), 0);
  viscosity.assign(mats.size(), 0);
  boundary_viscosity.assign(mats.size(), 0);
  for (std::size_t m = 0; m < mats.size(); ++m) {
    if (mats[m].type != ParticleType::Liquid) continue;
    rest_density[m] = Real(mats[m].param("density"));
    viscosity[m] = Real(mats[m].param("viscosity"));
    boundary_viscosity[m] = Real(mats[m].param("boundary_viscosity"));
  }
}

void FluidNeighbourHandles::request(World& world) {
  fluid = world.request_neighbours(kLiquidMask, kLiquidMask);
  boundary = world.request_neighbours(kLiquidMask, kBoundaryMask);
}

FluidView make_fluid_view(const World& world, const FluidMaterialTable& materials,
                          const FluidNeighbourHandles& lists) {
  const Particles& p = world.particles();
  FluidView view;
  view.x = p.position.data();
  view.v = p.velocity.data();
  view.mass = p.mass.data();
  view.type = p.type.data();
  view.material = p.material.data();
  view.boundary_volume = p.boundary_volume.data();
  view.rest_density = materials.rest_density.data();
  view.viscosity = materials.viscosity.data();
  view.boundary_viscosity = materials.boundary_viscosity.data();
  view.fluid = view_of(world.neighbours(lists.fluid));
  view.boundary = view_of(world.neighbours(lists.boundary));
  view.kernel = world.kernel();
  return view;
}

}  // namespace upf
