// A fluid solver's step in a device pipeline (solver_part.h), for any backend and any pressure
// method (pcisph_method.h, wcsph_method.h, ...): FluidSolverState's shared stages around the
// method's own, on device arrays. Its lists: liquid -> liquid and liquid -> boundary, and body
// particles -> liquid when a body system takes the reactions. Stages "non_pressure" (shared forces,
// the grains' reactions from liquid_force, then the method's own), optionally "divergence",
// "pressure" (the method's) and "integration" (reactions on bodies, then symplectic Euler), timed
// like the CPU's. Every stage is the struct the CPU solver runs, so the bits are the CPU's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "device/solver_part.h"
#include "framework/boundary/slip_normal_fields.h"
#include "solvers/fluid/fluid_stages.h"

namespace upf::device {

// What a pressure method sees of a step: the view, the owned particles and the shared buffers.
struct FluidStep {
  FluidView f;
  NeighbourView fluid_of_boundary;  // body particles -> liquid; null offsets: no reactions wanted
  Vec3* boundary_force;             // the reactions on body particles
  ParticleRange owned;
  OwnedMaterials owns;
  std::size_t n;  // all particles
  Real dt;
  Real* density;
  Real* pressure;
  FluidGradients fluid_gradient;
  Vec3* boundary_gradient;
  Vec3* other_acceleration;
  Vec3* pressure_acceleration;
};

template <class Backend, class Method>
class FluidPart final : public SolverPart<Backend> {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  FluidPart(FluidSetup setup, typename Method::Setup method, PipelineState<Backend>& state)
      : setup_(std::move(setup)), method_(std::move(method)), stages_(setup_.stages) {
    copy_to_device(rest_density_, setup_.rest_density);
    copy_to_device(viscosity_, setup_.viscosity);
    copy_to_device(boundary_viscosity_, setup_.boundary_viscosity);
    copy_to_device(cohesion_, setup_.cohesion);
    copy_to_device(adhesion_, setup_.adhesion);
    copy_to_device(owns_, setup_.owns);
    fluid_list_ = state.lists.request(kLiquidMask, kLiquidMask);
    boundary_list_ = state.lists.request(kLiquidMask, kBoundaryMask);
    if (setup_.wall_friction) wall_list_ = state.lists.request(kBoundaryMask, kLiquidMask);
    if (setup_.reaction_query != 0)
      reaction_list_ = state.lists.request(setup_.reaction_query, kLiquidMask);
  }

  void bind(PipelineState<Backend>& state) override {
    density_ = &state.particles.scalar_array(setup_.density);
    pressure_ = &state.particles.scalar_array(setup_.pressure);
    pressure_acceleration_ = &state.particles.vector_array(kPressureAccelerationField);
    surface_normal_ = setup_.surface_model != SurfaceTensionModel::None
                          ? &state.particles.vector_array(kSurfaceNormalField)
                          : nullptr;
    if (setup_.surface_model == SurfaceTensionModel::ContinuumSurfaceForce) {
      surface_curvature_ = &state.particles.scalar_array(kSurfaceCurvatureField);
      surface_curvature_weight_ = &state.particles.scalar_array(kSurfaceCurvatureWeightField);
      surface_smoothed_normal_ = &state.particles.vector_array(kSurfaceSmoothedNormalField);
    }
    method_.bind(state.particles);
  }

  const StageRunner& stages() const override { return stages_; }
  SolverStats stats() const override { return stats_; }

  std::size_t bytes() const override {
    return bytes_of(owned_) + bytes_of(fluid_gradient_) + bytes_of(boundary_gradient_) +
           bytes_of(other_acceleration_) + method_.bytes() + bytes_of(rest_density_) +
           bytes_of(viscosity_) + bytes_of(boundary_viscosity_) + bytes_of(cohesion_) +
           bytes_of(adhesion_) + bytes_of(owns_);
  }

  void step(PipelineState<Backend>& state, Real dt) override {
    stages_.clear();
    const std::size_t n = state.particles.size();
    const DeviceExecutor<Backend> exec{state.ghosts};
    FluidStep step{};
    step.n = n;
    step.dt = dt;
    step.density = raw<Real>(*density_);
    step.pressure = raw<Real>(*pressure_);
    step.owns = owned_materials();
    if (reaction_list_ >= 0 && state.boundary_force_or_null()) {
      step.fluid_of_boundary = state.lists.view(reaction_list_);
      step.boundary_force = state.boundary_force_or_null();
    }
    Vec3* liquid_force = state.liquid_force_or_null();

    stages_("non_pressure", [&] {
      step.owned = indices_where<Backend>(
          state.owned,
          part_detail::OwnedIndex{raw<MaterialId>(state.particles.material), step.owns}, owned_);
      // Recomputed where used unless the setup asks to store them (FluidGradients).
      fluid_gradient_.resize(setup_.store_gradients ? state.lists.list(fluid_list_).total() : 0);
      boundary_gradient_.resize(n);
      other_acceleration_.resize(n);
      step.f = fluid_view(state);
      if (body_wall_reactions(setup_.wall_pressure, setup_.reaction_query)) {
        step.f.body_wall_factor = raw<Real>(state.particles.scalar_array(kBodyWallFactorField));
        step.f.body_wall_floor = raw<Real>(state.particles.scalar_array(kBodyWallFloorField));
        step.f.body = raw<BodyId>(state.particles.body);
      }
      ImplicitViscosityStep viscous;
      ImplicitViscosityArrays viscosity_arrays{};
      if (setup_.implicit_viscosity) {
        viscosity_arrays = implicit_viscosity_arrays(
            [&](const char* name) { return raw<Vec3>(state.particles.vector_array(name)); });
        step.f.solved_velocity = viscosity_arrays.solution;
        viscous = {&viscosity_arrays, setup_.viscosity_solve, step.owns, n, dt};
      }
      step.fluid_gradient =
          setup_.store_gradients ? FluidGradients(raw<Vec3>(fluid_gradient_)) : FluidGradients();
      step.boundary_gradient = raw<Vec3>(boundary_gradient_);
      step.other_acceleration = raw<Vec3>(other_acceleration_);
      step.pressure_acceleration = raw<Vec3>(*pressure_acceleration_);
      Vec3* wall_velocity = nullptr;
      if (wall_list_ >= 0) {
        wall_velocity = raw<Vec3>(state.particles.vector_array(kWallVelocityField));
        step.f.wall_velocity = wall_velocity;
      }
      NonPressureArrays arrays{step.fluid_gradient,
                               step.boundary_gradient,
                               step.other_acceleration,
                               step.density,
                               liquid_force,
                               step.pressure,
                               surface_normal_ ? raw<Vec3>(*surface_normal_) : nullptr,
                               wall_list_ >= 0 ? state.lists.view(wall_list_) : NeighbourView{},
                               wall_velocity,
                               n,
                               step.fluid_of_boundary,
                               step.boundary_force,
                               step.owns};
      if (surface_curvature_) {
        arrays.surface_curvature = raw<Real>(*surface_curvature_);
        arrays.surface_curvature_weight = raw<Real>(*surface_curvature_weight_);
        arrays.surface_smoothed_normal = raw<Vec3>(*surface_smoothed_normal_);
      }
      const ImplicitViscosityStats viscosity_stats =
          run_non_pressure_stages(exec, step.owned, step.f, arrays, state.world.gravity, viscous);
      viscosity_iterations_ = viscosity_stats.iterations;
      method_.non_pressure(exec, step);
    });

    if constexpr (Method::kDivergenceStage)
      stages_("divergence", [&] { method_.divergence(exec, step); });

    stages_("pressure", [&] {
      stats_ = method_.pressure(exec, step);
      if (setup_.implicit_viscosity) stats_.viscosity_iterations = viscosity_iterations_;
    });

    stages_("integration", [&] {
      if (step.boundary_force) method_.add_reactions(exec, step);
      if constexpr (Method::kOwnIntegration) {
        method_.integrate(exec, step, raw<Vec3>(state.particles.velocity),
                          raw<Vec3>(state.particles.position));
      } else {
        run<Backend>(step.owned,
                     SymplecticEulerStage{step.other_acceleration, step.pressure_acceleration, dt,
                                          raw<Vec3>(state.particles.velocity),
                                          raw<Vec3>(state.particles.position)});
      }
    });
  }

 private:
  OwnedMaterials owned_materials() const { return {raw<std::uint8_t>(owns_), owns_.size()}; }

  // The free-slip walls' normals, or null without any (framework/boundary/slip_normal.h).
  static const Vec3* slip_normal(const PipelineState<Backend>& state) {
    const auto* normal = state.particles.find_vector(kSlipNormalField);
    return normal ? raw<Vec3>(*normal) : nullptr;
  }

  FluidView fluid_view(const PipelineState<Backend>& state) const {
    const DeviceParticles<Backend>& p = state.particles;
    FluidView f;
    f.x = raw<Vec3>(p.position);
    f.v = raw<Vec3>(p.velocity);
    f.mass = raw<Real>(p.mass);
    f.type = raw<ParticleType>(p.type);
    f.material = raw<MaterialId>(p.material);
    f.boundary_volume = raw<Real>(p.boundary_volume);
    f.rest_density = raw<Real>(rest_density_);
    f.viscosity = raw<Real>(viscosity_);
    f.boundary_viscosity = raw<Real>(boundary_viscosity_);
    f.viscosity_factor = setup_.viscosity_factor;
    f.fluid = state.lists.view(fluid_list_);
    f.boundary = state.lists.view(boundary_list_);
    f.kernel = CubicSplineKernel(state.world.support_radius);
    f.wall_pressure = setup_.wall_pressure;
    f.density_contrast = setup_.density_contrast;
    f.surface.model = setup_.surface_model;
    f.surface.cohesion = raw<Real>(cohesion_);
    f.surface.adhesion = raw<Real>(adhesion_);
    f.surface.materials = std::uint32_t(setup_.rest_density.size());
    f.surface.has_adhesion = setup_.has_adhesion;
    if (surface_normal_) f.surface.normal = raw<Vec3>(*surface_normal_);
    if (surface_curvature_) {
      f.surface.curvature = raw<Real>(*surface_curvature_);
      f.surface.curvature_weight = raw<Real>(*surface_curvature_weight_);
      f.surface.smoothed_normal = raw<Vec3>(*surface_smoothed_normal_);
    }
    f.slip_normal = slip_normal(state);
    return f;
  }

  FluidSetup setup_;
  Method method_;
  StageRunner stages_;
  SolverStats stats_;
  int viscosity_iterations_ = -1;
  int fluid_list_ = -1, boundary_list_ = -1, reaction_list_ = -1, wall_list_ = -1;
  vector<Real> rest_density_, viscosity_, boundary_viscosity_, cohesion_, adhesion_;
  vector<std::uint8_t> owns_;
  vector<std::uint32_t> owned_;
  vector<Vec3> fluid_gradient_, boundary_gradient_, other_acceleration_;
  // The particles' scratch fields, as on the CPU: ghosts and periodic images carry them.
  vector<Vec3>* pressure_acceleration_ = nullptr;
  vector<Vec3>* surface_normal_ = nullptr;
  vector<Real>* surface_curvature_ = nullptr;
  vector<Real>* surface_curvature_weight_ = nullptr;
  vector<Vec3>* surface_smoothed_normal_ = nullptr;
  vector<Real>* density_ = nullptr;
  vector<Real>* pressure_ = nullptr;
};

}  // namespace upf::device
