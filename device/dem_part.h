// The DEM solver's step (dem_solver.h) in a device pipeline (solver_part.h): the contact list
// (device_dem_contacts.h), the fluid state around each grain, velocity Verlet sub-steps with
// grain-grain, grain-wall and grain-body contacts (dem_steps.h, the CPU solver's own template),
// the reactions on rigid particles into boundary_force and on the liquid into liquid_force. Its
// lists are the CPU solver's: grains -> grains and boundary particles and rigid -> grains at the
// candidates' radius; grains -> liquid, grains -> grains and liquid -> grains at the support
// radius when the scene has liquid. The springs start from the host solver's and go back to it
// for checkpoints (download_state).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <thrust/fill.h>

#include "device/device_dem_contacts.h"
#include "device/solver_part.h"
#include "solvers/dem/dem_steps.h"

namespace upf::device {

template <class Backend>
class DemPart final : public SolverPart<Backend> {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  DemPart(DemSolverSetup setup, PipelineState<Backend>& state)
      : setup_(std::move(setup)), stages_(setup_.stages) {
    const DemStepSetup& s = setup_.step;
    copy_to_device(pairs_, s.pairs);
    copy_to_device(walls_, s.walls);
    copy_to_device(boundary_, s.boundary);
    copy_to_device(owns_, s.owns);
    copy_to_device(boxes_, s.boxes);
    copy_to_device(liquid_density_, s.liquid_density);
    copy_to_device(liquid_viscosity_, s.liquid_viscosity);
    const TypeMask grains = mask_of(ParticleType::Granular);
    grains_list_ = state.lists.request(grains, grains | kBoundaryMask, s.list_radius);
    if (s.reactions)
      reaction_list_ = state.lists.request(mask_of(ParticleType::Rigid), grains, s.list_radius);
    if (s.liquid) {
      grain_liquid_list_ = state.lists.request(grains, kLiquidMask);
      grain_voidage_list_ = state.lists.request(grains, grains);
      liquid_grain_list_ = state.lists.request(kLiquidMask, grains);
    }
  }

  void bind(PipelineState<Backend>& state) override {
    DeviceParticles<Backend>& p = state.particles;
    radius_ = &p.scalar_array(setup_.step.radius);
    angular_velocity_ = &p.vector_array(setup_.step.angular_velocity);
    force_ = &p.vector_array(setup_.step.force);
    torque_ = &p.vector_array(setup_.step.torque);
    wall_normal_ = &p.vector_array(setup_.step.wall_normal);
    wall_shear_ = &p.vector_array(setup_.step.wall_shear);
    contact_load_ = &p.scalar_array(setup_.step.contact_load);
    const DemSpringState springs = setup_.load_springs();
    primed_ = springs.primed;
    contacts_.set_springs(springs);
  }

  void download_state() const override {
    DemSpringState springs;
    springs.primed = primed_;
    contacts_.springs_into(springs);
    setup_.store_springs(springs);
  }

  const StageRunner& stages() const override { return stages_; }
  SolverStats stats() const override { return stats_; }

  std::size_t bytes() const override {
    return contacts_.bytes() + bytes_of(pairs_) + bytes_of(walls_) + bytes_of(boundary_) +
           bytes_of(owns_) + bytes_of(boxes_) + bytes_of(liquid_density_) +
           bytes_of(liquid_viscosity_) + bytes_of(owned_) + bytes_of(rigid_) + bytes_of(fluid_) +
           bytes_of(fluid_weight_sum_) + bytes_of(start_position_) + bytes_of(fluid_force_);
  }

  void step(PipelineState<Backend>& state, Real dt) override {
    stages_.clear();
    stats_ = SolverStats{};
    const DemStepSetup& s = setup_.step;
    const int substeps = std::max(1, int(std::ceil(double(dt) / double(s.substep) - 1e-9)));
    const Real h = dt / Real(substeps);
    const DeviceExecutor<Backend> exec;
    DeviceParticles<Backend>& p = state.particles;
    const std::size_t n = p.size();
    DemArrays a{};
    stages_("dem_contacts", [&] {
      const ParticleRange owned = indices_where<Backend>(
          n, part_detail::OwnedIndex{raw<MaterialId>(p.material), owned_materials()}, owned_);
      ParticleRange rigid{nullptr, 0};
      if (reaction_list_ >= 0)
        rigid = indices_where<Backend>(
            n, part_detail::TypeIs{raw<ParticleType>(p.type), ParticleType::Rigid}, rigid_);
      const DemCandidateSources sources{
          raw<Vec3>(p.position),
          raw<ParticleType>(p.type),
          raw<MaterialId>(p.material),
          raw<ParticleId>(p.id),
          raw<BodyId>(p.body),
          raw<Real>(*radius_),
          owned_materials(),
          state.lists.view(grains_list_),
          reaction_list_ >= 0 ? state.lists.view(reaction_list_) : NeighbourView{nullptr, nullptr},
          raw<ContainerBox>(boxes_),
          std::uint32_t(boxes_.size()),
          s.skin,
          std::uint32_t(n)};  // one rank: no ghosts
      contacts_.rebuild(sources, owned, n, state.id_bound, raw<ParticleId>(p.id));
      if (s.liquid) interpolate_fluid(state, owned);
      a = arrays(state, owned, rigid);
      if (!primed_) {
        run_dem_first_forces(exec, a, h);
        primed_ = true;
      }
    });
    run_dem_substeps(exec, a, dt, substeps, h, stages_);
    if (s.liquid_force && state.liquid_force_or_null())
      stages_("dem_contacts", [&] {
        run<Backend>(all_particles(n),
                     DemLiquidReactionStage{state.lists.view(liquid_grain_list_), kernel(state),
                                            raw<Vec3>(start_position_), raw<Real>(p.mass),
                                            raw<ParticleType>(p.type), raw<MaterialId>(p.material),
                                            raw<Real>(liquid_density_), owned_materials(),
                                            raw<Real>(fluid_weight_sum_), raw<Vec3>(fluid_force_),
                                            state.liquid_force_or_null()});
      });
    stats_.iterations = substeps;
  }

 private:
  template <class T>
  static void zeroed(vector<T>& v, std::size_t n) {
    v.resize(n);
    thrust::fill(Backend::policy(), v.begin(), v.end(), T{});
  }

  OwnedMaterials owned_materials() const { return {raw<std::uint8_t>(owns_), owns_.size()}; }
  static CubicSplineKernel kernel(const PipelineState<Backend>& state) {
    return CubicSplineKernel(state.world.support_radius);
  }

  // DemSolver::interpolate_fluid.
  void interpolate_fluid(PipelineState<Backend>& state, ParticleRange owned) {
    DeviceParticles<Backend>& p = state.particles;
    const std::size_t n = p.size();
    zeroed(fluid_, n);
    zeroed(fluid_weight_sum_, n);
    zeroed(fluid_force_, n);
    start_position_.resize(n);
    thrust::copy(Backend::policy(), p.position.begin(), p.position.end(), start_position_.begin());
    run<Backend>(owned,
                 DemFluidStateStage{
                     state.lists.view(grain_liquid_list_), state.lists.view(grain_voidage_list_),
                     kernel(state), raw<Vec3>(p.position), raw<Vec3>(p.velocity), raw<Real>(p.mass),
                     raw<ParticleType>(p.type), raw<MaterialId>(p.material), raw<Real>(*radius_),
                     raw<Real>(liquid_density_), raw<Real>(liquid_viscosity_),
                     raw<Real>(fluid_weight_sum_), raw<GrainFluidState>(fluid_)});
  }

  // DemSolver::arrays.
  DemArrays arrays(PipelineState<Backend>& state, ParticleRange owned, ParticleRange rigid) {
    DeviceParticles<Backend>& p = state.particles;
    const DemStepSetup& s = setup_.step;
    DemArrays a{};
    a.model = s.model;
    a.contacts = contacts_.view();
    a.pairs = DemPairTable{raw<DemPairParams>(pairs_), raw<DemPairParams>(walls_),
                           raw<DemPairParams>(boundary_), s.materials, s.boundary_radius};
    a.owned = owned;
    a.holders = owned;
    a.rigid = rigid;
    a.x = raw<Vec3>(p.position);
    a.v = raw<Vec3>(p.velocity);
    a.w = raw<Vec3>(*angular_velocity_);
    a.mass = raw<Real>(p.mass);
    a.radius = raw<Real>(*radius_);
    a.type = raw<ParticleType>(p.type);
    a.material = raw<MaterialId>(p.material);
    a.boxes = raw<ContainerBox>(boxes_);
    a.gravity = s.gravity;
    a.fluid = fluid_.empty() ? nullptr : raw<GrainFluidState>(fluid_);
    a.fluid_force = fluid_force_.empty() ? nullptr : raw<Vec3>(fluid_force_);
    a.force = raw<Vec3>(*force_);
    a.torque = raw<Vec3>(*torque_);
    a.boundary_force = reaction_list_ >= 0 ? state.boundary_force_or_null() : nullptr;
    a.wall_normal = raw<Vec3>(*wall_normal_);
    a.wall_shear = raw<Vec3>(*wall_shear_);
    a.contact_load = raw<Real>(*contact_load_);
    return a;
  }

  DemSolverSetup setup_;
  StageRunner stages_;
  SolverStats stats_;
  int grains_list_ = -1, reaction_list_ = -1;
  int grain_liquid_list_ = -1, grain_voidage_list_ = -1, liquid_grain_list_ = -1;
  vector<DemPairParams> pairs_, walls_, boundary_;
  vector<std::uint8_t> owns_;
  vector<ContainerBox> boxes_;
  vector<Real> liquid_density_, liquid_viscosity_;
  vector<std::uint32_t> owned_, rigid_;
  DeviceDemContacts<Backend> contacts_;
  bool primed_ = false;
  vector<GrainFluidState> fluid_;
  vector<Real> fluid_weight_sum_;
  vector<Vec3> start_position_, fluid_force_;
  vector<Real>* radius_ = nullptr;
  vector<Vec3>* angular_velocity_ = nullptr;
  vector<Vec3>* force_ = nullptr;
  vector<Vec3>* torque_ = nullptr;
  vector<Vec3>* wall_normal_ = nullptr;
  vector<Vec3>* wall_shear_ = nullptr;
  vector<Real>* contact_load_ = nullptr;
};

}  // namespace upf::device
