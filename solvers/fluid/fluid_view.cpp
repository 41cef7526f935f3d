#include "solvers/fluid/fluid_view.h"

#include <algorithm>

#include "framework/world/world.h"
#include "solvers/fluid/surface_tension_models.h"

namespace upf {

void FluidMaterialTable::load(const World& world, const std::vector<MaterialId>& materials) {
  const auto& mats = world.materials().all();
  const std::size_t n = mats.size();
  rest_density.assign(n, 0);
  viscosity.assign(n, 0);
  boundary_viscosity.assign(n, 0);
  for (std::size_t m = 0; m < n; ++m) {
    if (mats[m].type != ParticleType::Liquid) continue;
    rest_density[m] = Real(mats[m].param("density"));
    viscosity[m] = Real(mats[m].param("viscosity"));
    boundary_viscosity[m] = Real(mats[m].param("boundary_viscosity"));
  }
  // Every liquid's, not only the solver's: the fluid lists hold every liquid particle.
  density_contrast = false;
  Real first = 0;  // the first liquid's rest density (>= 1 by its range)
  for (std::size_t m = 0; m < n; ++m) {
    if (mats[m].type != ParticleType::Liquid) continue;
    if (first == 0) first = rest_density[m];
    density_contrast = density_contrast || rest_density[m] != first;
  }
  implicit_viscosity = false;
  viscosity_tolerance = 1;
  viscosity_max_iterations = 1;
  for (MaterialId m : materials) {
    implicit_viscosity = implicit_viscosity || mats[m].param("implicit_viscosity") > 0;
    viscosity_tolerance = std::min(viscosity_tolerance, mats[m].param("viscosity_tolerance"));
    viscosity_max_iterations =
        std::max(viscosity_max_iterations, int(mats[m].param("viscosity_max_iterations")));
  }
  viscosity_operator = upf::viscosity_operator(
      world.settings().spacing, world.settings().support_radius(), implicit_viscosity);
  // Surface tension: the model of the solver's liquids with a sigma (the scene reader made them
  // agree); every liquid's coefficient under it, so that a neighbour of another solver pulls too.
  surface_model = SurfaceTensionModel::None;
  for (MaterialId m : materials)
    if (mats[m].param("surface_tension") > 0)
      surface_model = surface_tension_model_named(mats[m].surface_tension_model);
  cohesion.assign(n, 0);
  adhesion.assign(n * n, 0);
  has_adhesion = false;
  max_sigma_over_density = 0;
  if (surface_model == SurfaceTensionModel::None) return;
  const double support = world.settings().support_radius();
  const double spacing = world.settings().spacing;
  const double face_gradient = csf_face_gradient_per_area(spacing, support);
  for (std::size_t m = 0; m < n; ++m) {
    if (mats[m].type != ParticleType::Liquid) continue;
    const double sigma = mats[m].param("surface_tension");
    // Akinci's gamma: that model's coefficient, and every model's adhesion is a ratio to it
    // (docs/surface-tension.md). The continuum force's: sigma / (c0 rho0).
    const double gamma = akinci_gamma_for_sigma(sigma, rest_density[m], spacing, support);
    cohesion[m] = surface_model == SurfaceTensionModel::ContinuumSurfaceForce
                      ? Real(sigma / (face_gradient * rest_density[m]))
                      : Real(gamma);
    max_sigma_over_density = std::max(max_sigma_over_density, Real(sigma) / rest_density[m]);
    for (const auto& [name, ratio] : mats[m].adhesion) {
      const auto boundary = world.materials().find(name);
      if (!boundary || ratio <= 0) continue;
      adhesion[m * n + *boundary] = Real(ratio * gamma);
      has_adhesion = has_adhesion || gamma > 0;
    }
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
  view.viscosity_factor = Real(materials.viscosity_operator.laplacian_factor);
  view.density_contrast = materials.density_contrast;
  view.fluid = view_of(world.neighbours(lists.fluid));
  view.boundary = view_of(world.neighbours(lists.boundary));
  view.kernel = world.kernel();
  view.surface.model = materials.surface_model;
  view.surface.cohesion = materials.cohesion.data();
  view.surface.adhesion = materials.adhesion.data();
  view.surface.materials = std::uint32_t(materials.rest_density.size());
  view.surface.has_adhesion = materials.has_adhesion;
  return view;
}

}  // namespace upf
