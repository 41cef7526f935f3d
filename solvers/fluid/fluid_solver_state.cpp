#include "solvers/fluid/fluid_solver_state.h"

#include <algorithm>

#include "framework/boundary/slip_normal.h"
#include "framework/world/body_particle_stages.h"
#include "framework/world/world.h"
#include "solvers/fluid/fluid_forces.h"

namespace upf {

namespace {

// The free-slip walls' normals, or null without any (framework/boundary/slip_normal.h).
const Vec3* slip_normal(const World& world) {
  const std::vector<Vec3>* normal = world.particles().find_vector(kSlipNormalField);
  return normal ? normal->data() : nullptr;
}

}  // namespace

void FluidSolverState::prepare(World& world, const std::vector<MaterialId>& materials) {
  Particles& p = world.particles();
  density_field = p.declare_scalar("density", 0, true);
  pressure_field = p.declare_scalar("pressure", 0, true);
  pressure_acceleration_field = p.declare_scratch_vector(kPressureAccelerationField);
  lists.request(world);
  // Reactions are gathered from the bodies' side: for each body particle, its liquid neighbours.
  reaction_query =
      world.coupling().active(CouplingArray::BoundaryForce) ? body_reaction_query(p) : TypeMask(0);
  if (reaction_query != 0) reaction_list = world.request_neighbours(reaction_query, kLiquidMask);
  if (body_wall_reactions(wall_pressure, reaction_query)) {
    p.declare_scratch_scalar(kBodyWallFactorField);
    p.declare_scratch_scalar(kBodyWallFloorField);
  }
  table.load(world, materials);
  if (surface_tension()) surface_normal_field = p.declare_scratch_vector(kSurfaceNormalField);
  if (table.surface_model == SurfaceTensionModel::ContinuumSurfaceForce) {
    p.declare_scratch_scalar(kSurfaceCurvatureField);
    p.declare_scratch_scalar(kSurfaceCurvatureWeightField);
    p.declare_scratch_vector(kSurfaceSmoothedNormalField);
  }
  owned.set_materials(world.materials().size(), materials);
  bool wall_friction = false;
  for (MaterialId m : materials) wall_friction = wall_friction || table.boundary_viscosity[m] > 0;
  if (wall_friction) {
    wall_list = world.request_neighbours(kBoundaryMask, kLiquidMask);
    wall_velocity_field = p.declare_scratch_vector(kWallVelocityField);
  }
  max_viscosity = 0;
  if (!implicit_viscosity()) {
    for (MaterialId m : materials) max_viscosity = std::max(max_viscosity, table.viscosity[m]);
  } else {
    // Names from implicit_viscosity.h; the last, the warm start, lives across steps.
    for (int k = 0; k + 1 < kImplicitViscosityFieldCount; ++k)
      p.declare_scratch_vector(kImplicitViscosityFields[k]);
    p.declare_vector(kImplicitViscosityFields[kImplicitViscosityFieldCount - 1]);
  }
}

FluidView FluidSolverState::begin_step(World& world) {
  const std::size_t n = world.particles().size();
  owned.rebuild(world.particles());
  fluid_gradient.resize(world.neighbours(lists.fluid).total());
  boundary_gradient.resize(n);
  other_acceleration.resize(n);
  pressure_acceleration = world.particles()[pressure_acceleration_field].data();
  FluidView f = make_fluid_view(world, table, lists);
  f.wall_pressure = wall_pressure;
  surface_normal = surface_tension() ? world.particles()[surface_normal_field].data() : nullptr;
  f.surface.normal = surface_normal;
  if (table.surface_model == SurfaceTensionModel::ContinuumSurfaceForce) {
    surface_curvature = world.particles().scalar_field(kSurfaceCurvatureField).data();
    surface_curvature_weight = world.particles().scalar_field(kSurfaceCurvatureWeightField).data();
    surface_smoothed_normal = world.particles().vector_field(kSurfaceSmoothedNormalField).data();
  } else {
    surface_curvature = surface_curvature_weight = nullptr;
    surface_smoothed_normal = nullptr;
  }
  f.surface.curvature = surface_curvature;
  f.surface.curvature_weight = surface_curvature_weight;
  f.surface.smoothed_normal = surface_smoothed_normal;
  wall_velocity = wall_list >= 0 ? world.particles()[wall_velocity_field].data() : nullptr;
  f.wall_velocity = wall_velocity;
  f.slip_normal = slip_normal(world);
  if (body_wall_reactions(wall_pressure, reaction_query)) {
    f.body_wall_factor = world.particles().scalar_field(kBodyWallFactorField).data();
    f.body_wall_floor = world.particles().scalar_field(kBodyWallFloorField).data();
    f.body = world.particles().body.data();
  }
  if (implicit_viscosity()) {
    Particles& p = world.particles();
    viscosity_arrays =
        implicit_viscosity_arrays([&](const char* name) { return p.vector_field(name).data(); });
    f.solved_velocity = viscosity_arrays.solution;
  }
  return f;
}

void FluidSolverState::initial_density(World& world) {
  const FluidView f = begin_step(world);
  Real* density = world.particles()[density_field].data();
  world.executor().run(owned.range(),
                       DensityAndGradientsStage{f, FluidGradients(fluid_gradient.data()),
                                                boundary_gradient.data(), density});
}

void FluidSolverState::shared_forces(World& world, const FluidView& f, Real* density, Real dt) {
  const Vec3* liquid_force = world.coupling().active(CouplingArray::LiquidForce)
                                 ? world.coupling()[CouplingArray::LiquidForce].data()
                                 : nullptr;
  const Real* pressure = world.particles()[pressure_field].data();
  ImplicitViscosityStep viscous;
  if (implicit_viscosity())
    viscous = {&viscosity_arrays,
               {table.viscosity_tolerance, table.viscosity_max_iterations},
               owned.materials(),
               world.particles().size(),
               dt};
  NonPressureArrays arrays{
      fluid_gradient.data(),
      boundary_gradient.data(),
      other_acceleration.data(),
      density,
      liquid_force,
      pressure,
      surface_normal,
      wall_list >= 0 ? view_of(world.neighbours(wall_list)) : NeighbourView{},
      wall_velocity,
      world.particles().size(),
      reaction_list >= 0 ? view_of(world.neighbours(reaction_list)) : NeighbourView{},
      reaction_list >= 0 ? world.coupling()[CouplingArray::BoundaryForce].data() : nullptr,
      owned.materials()};
  arrays.surface_curvature = surface_curvature;
  arrays.surface_curvature_weight = surface_curvature_weight;
  arrays.surface_smoothed_normal = surface_smoothed_normal;
  viscosity_stats = run_non_pressure_stages(world.executor(), owned.range(), f, arrays,
                                            world.settings().gravity, viscous);
}

void FluidSolverState::predict_unowned(const World& world, const FluidView& f, Vec3* x_star,
                                       Real dt) const {
  world.executor().run(all_particles(world.particles().size()),
                       PredictUnownedStage{f, owned.materials(), dt, x_star});
}

void FluidSolverState::integrate(World& world, Real dt) const {
  Particles& p = world.particles();
  world.executor().run(owned.range(),
                       SymplecticEulerStage{other_acceleration.data(), pressure_acceleration, dt,
                                            p.velocity.data(), p.position.data()});
}

}  // namespace upf
