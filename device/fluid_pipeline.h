// A fluid solver's step on the device pipeline, for any backend and any pressure method
// (pcisph_method.h, wcsph_method.h): the world's step (World::step) and the fluid solvers' shared
// step (FluidSolverState) with the solvers' own stage structs and orchestration, on device arrays.
//
// A step: the last good state (a device copy), the bodies' placement (device_bodies.h, driven by
// the host's body system), reordering on the world's cadence, the device grid's lists (liquid ->
// liquid, liquid -> boundary, and rigid -> liquid when bodies take reactions), then the three
// stages "non_pressure" (shared forces, then the method's own), "pressure" (the method's) and
// "integration" (reactions on bodies, then symplectic Euler), timed like the CPU's. Every
// per-particle stage and every reduction gives the CPU executor's bits (device_primitives.h,
// device_grid.h), so frames of this pipeline equal the CPU's bit for bit (tests/device). Scenes it
// does not cover yet are refused by make_device_pipeline, never run half-way. Its inputs are plain
// values (pcisph_setup.h): no world header reaches nvcc.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <thrust/copy.h>
#include <thrust/fill.h>
#include <thrust/sort.h>

#include "device/device_bodies.h"
#include "device/device_grid.h"
#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/fluid_setup.h"
#include "framework/core/stopwatch.h"
#include "framework/particles/kinetic_energy.h"
#include "framework/solver/stage_runner.h"
#include "framework/world/device_pipeline.h"
#include "solvers/fluid/fluid_stages.h"

namespace upf::device {

namespace pipeline_detail {

struct OwnedIndex {
  const MaterialId* material;
  OwnedMaterials owns;
  UPF_HD bool operator()(std::uint32_t i) const { return owns(material[i]); }
};

struct LiquidSpeedSquared {
  const Vec3* v;
  const ParticleType* type;
  UPF_HD Real operator()(std::uint32_t i) const {
    return type[i] == ParticleType::Liquid ? squared_norm(v[i]) : Real(0);
  }
};

// World::check_stability's test, device-clean.
struct BrokenParticle {
  const Vec3* x;
  const Vec3* v;
  double limit2;
  UPF_HD bool operator()(std::uint32_t i) const {
    return !is_finite(x[i]) || !is_finite(v[i]) || double(squared_norm(v[i])) > limit2;
  }
};

// Block b of block_sum (deterministic_sum.h): its values added in index order.
template <class Value>
struct BlockSumStage {
  Value value;
  std::size_t n;
  double* partial;
  UPF_HD void operator()(std::size_t b) const {
    double s = 0;
    const std::size_t end = (b + 1) * kBlockSumSize < n ? (b + 1) * kBlockSumSize : n;
    for (std::size_t i = b * kBlockSumSize; i < end; ++i) s += value(i);
    partial[b] = s;
  }
};

}  // namespace pipeline_detail

// What a pressure method sees of a step: the view, the owned particles and the shared buffers.
struct FluidStep {
  FluidView f;
  NeighbourView fluid_of_boundary;  // rigid -> liquid; null offsets: no reactions wanted
  Vec3* boundary_force;             // the reactions on rigid particles
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
class FluidPipeline final : public DevicePipeline {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  FluidPipeline(FluidSetup setup, typename Method::Setup method)
      : setup_(std::move(setup)),
        method_(std::move(method)),
        grid_(setup_.support_radius),
        stages_(setup_.stages),
        threads_(setup_.threads) {
    copy_in(rest_density_, setup_.rest_density);
    copy_in(viscosity_, setup_.viscosity);
    copy_in(boundary_viscosity_, setup_.boundary_viscosity);
    copy_in(owns_, setup_.owns);
  }

  std::string_view name() const override { return Backend::name; }

  void upload(const Particles& particles) override {
    const typename Backend::ThreadScope threads(threads_);
    particles_.upload(particles);
    for (int t = 0; t < kParticleTypeCount; ++t) counts_[t] = particles.count(ParticleType(t));
    density_ = &particles_.scalar_array(setup_.density);
    pressure_ = &particles_.scalar_array(setup_.pressure);
    method_.bind(particles_);
  }

  void download(Particles& p) const override { particles_.download(p); }
  void download_last_good(Particles& into) const override { last_good_.download_snapshot(into); }

  Real max_liquid_speed_squared() const override {
    const typename Backend::ThreadScope threads(threads_);
    return max_of<Backend>(all_particles(particles_.size()),
                           pipeline_detail::LiquidSpeedSquared{raw<Vec3>(particles_.velocity),
                                                               raw<ParticleType>(particles_.type)});
  }

  double kinetic_energy() const override {
    const typename Backend::ThreadScope threads(threads_);
    const std::size_t n = particles_.size();
    const std::size_t blocks = (n + kBlockSumSize - 1) / kBlockSumSize;
    block_partials_.resize(blocks);
    for_each_index<Backend>(
        blocks, pipeline_detail::BlockSumStage<KineticEnergyValue>{
                    KineticEnergyValue{raw<Real>(particles_.mass), raw<Vec3>(particles_.velocity)},
                    n, raw<double>(block_partials_)});
    // The blocks in order, on the host, as block_sum adds them.
    double total = 0;
    for (double p : std::vector<double>(block_partials_.begin(), block_partials_.end())) total += p;
    return total;
  }

  std::size_t count(ParticleType t) const override { return counts_[int(t)]; }

  std::size_t device_bytes() const override {
    return particles_.bytes() + last_good_.bytes() + grid_.bytes() + fluid_list_.bytes() +
           boundary_list_.bytes() + bytes_of(owned_) + bytes_of(fluid_gradient_) +
           bytes_of(boundary_gradient_) + bytes_of(other_acceleration_) +
           bytes_of(pressure_acceleration_) + method_.bytes() + bytes_of(rest_density_) +
           bytes_of(viscosity_) + bytes_of(boundary_viscosity_) + bytes_of(owns_) +
           reaction_list_.bytes() + bytes_of(boundary_force_) + bodies_.bytes() +
           bytes_of(block_partials_);
  }

  std::size_t first_broken_particle(double max_speed) const override {
    const typename Backend::ThreadScope threads(threads_);
    return first_by_id<Backend>(
        particles_.size(), raw<ParticleId>(particles_.id),
        pipeline_detail::BrokenParticle{raw<Vec3>(particles_.position),
                                        raw<Vec3>(particles_.velocity), max_speed * max_speed});
  }

  void save_last_good() override {
    const typename Backend::ThreadScope threads(threads_);
    particles_.snapshot_into(last_good_);
  }

  void place_body_particles(const std::vector<BodyPose>& poses,
                            const std::string& local_field) override {
    const typename Backend::ThreadScope threads(threads_);
    bodies_.place(particles_, poses, local_field);
  }

  void body_wrenches(const std::vector<Vec3d>& origins,
                     std::vector<BodyWrench>& wrenches) override {
    const typename Backend::ThreadScope threads(threads_);
    bodies_.wrenches(particles_, boundary_force_, origins, wrenches);
  }

  void guard_body_surfaces(const std::vector<BodyPose>& poses,
                           const std::vector<const MeshParityData*>& meshes, double layer_depth,
                           double clearance, const std::string& local_field,
                           const std::string& normal_field,
                           std::vector<SurfaceHit>& hits) override {
    const typename Backend::ThreadScope threads(threads_);
    bodies_.guard(particles_, boundary_list_.view(), poses, meshes, layer_depth, clearance,
                  local_field, normal_field, hits);
  }

  void step(std::uint64_t step_count, double dt, StepReport& report) override {
    const typename Backend::ThreadScope threads(threads_);
    const Stopwatch neighbours;
    update_neighbours(step_count);
    report.neighbour_ms = neighbours.elapsed_ms();
    stages_.clear();
    solver_step(Real(dt));
    for (std::size_t j = 0; j < stages_.names().size(); ++j)
      report.stage_ms.emplace_back(stages_.names()[j], stages_.ms()[j]);
    report.solver = stats_;
  }

 private:
  template <class T>
  static void copy_in(vector<T>& to, const std::vector<T>& from) {
    to.resize(from.size());
    thrust::copy(from.begin(), from.end(), to.begin());
  }

  const ParticleType* type() const { return raw<ParticleType>(particles_.type); }

  // World::step's reordering and update_neighbours.
  void update_neighbours(std::uint64_t step_count) {
    const std::size_t n = particles_.size();
    const int every = setup_.reorder_every;
    auto build = [&] {
      grid_.build(raw<Vec3>(particles_.position), raw<ParticleId>(particles_.id), type(), n);
    };
    if (every > 0 && step_count % std::uint64_t(every) == 0) {
      build();
      particles_.permute(grid_.sorted_order());
    }
    build();
    const TypeMask targets[2] = {kLiquidMask, kBoundaryMask};
    DeviceNeighbourList<Backend>* outs[2] = {&fluid_list_, &boundary_list_};
    grid_.find_neighbours(type(), kLiquidMask, targets, 2, setup_.support_radius, outs);
    if (setup_.reactions) {
      const TypeMask liquid[1] = {kLiquidMask};
      DeviceNeighbourList<Backend>* reaction[1] = {&reaction_list_};
      grid_.find_neighbours(type(), mask_of(ParticleType::Rigid), liquid, 1, setup_.support_radius,
                            reaction);
    }
  }

  FluidView fluid_view() const {
    FluidView f;
    f.x = raw<Vec3>(particles_.position);
    f.v = raw<Vec3>(particles_.velocity);
    f.mass = raw<Real>(particles_.mass);
    f.type = type();
    f.material = raw<MaterialId>(particles_.material);
    f.boundary_volume = raw<Real>(particles_.boundary_volume);
    f.rest_density = raw<Real>(rest_density_);
    f.viscosity = raw<Real>(viscosity_);
    f.boundary_viscosity = raw<Real>(boundary_viscosity_);
    f.fluid = fluid_list_.view();
    f.boundary = boundary_list_.view();
    f.kernel = CubicSplineKernel(setup_.support_radius);
    return f;
  }

  OwnedMaterials owned_materials() const { return {raw<std::uint8_t>(owns_), owns_.size()}; }

  // OwnedParticles::rebuild: the owned particles in index order.
  ParticleRange rebuild_owned() {
    const std::size_t n = particles_.size();
    owned_.resize(n);
    const auto last = thrust::copy_if(
        Backend::policy(), thrust::counting_iterator<std::uint32_t>(0),
        thrust::counting_iterator<std::uint32_t>(std::uint32_t(n)), owned_.begin(),
        pipeline_detail::OwnedIndex{raw<MaterialId>(particles_.material), owned_materials()});
    return {raw<std::uint32_t>(owned_), std::size_t(last - owned_.begin())};
  }

  // FluidSolverState's shared stages around the method's.
  void solver_step(Real dt) {
    const std::size_t n = particles_.size();
    const DeviceExecutor<Backend> exec;
    FluidStep step{};
    step.n = n;
    step.dt = dt;
    step.density = raw<Real>(*density_);
    step.pressure = raw<Real>(*pressure_);
    step.owns = owned_materials();
    // The world's coupling arrays start each step at zero.
    if (setup_.reactions) {
      boundary_force_.resize(n);
      thrust::fill(Backend::policy(), boundary_force_.begin(), boundary_force_.end(), Vec3{});
      step.fluid_of_boundary = reaction_list_.view();
      step.boundary_force = raw<Vec3>(boundary_force_);
    }

    stages_("non_pressure", [&] {
      step.owned = rebuild_owned();
      // Recomputed where used unless the setup asks to store them (FluidGradients).
      fluid_gradient_.resize(setup_.store_gradients ? fluid_list_.total() : 0);
      boundary_gradient_.resize(n);
      other_acceleration_.resize(n);
      pressure_acceleration_.resize(n);
      step.f = fluid_view();
      step.fluid_gradient =
          setup_.store_gradients ? FluidGradients(raw<Vec3>(fluid_gradient_)) : FluidGradients();
      step.boundary_gradient = raw<Vec3>(boundary_gradient_);
      step.other_acceleration = raw<Vec3>(other_acceleration_);
      step.pressure_acceleration = raw<Vec3>(pressure_acceleration_);
      run_non_pressure_stages(exec, step.owned, step.f,
                              {step.fluid_gradient, step.boundary_gradient, step.other_acceleration,
                               step.density, nullptr},
                              setup_.gravity);
      method_.non_pressure(exec, step);
    });

    if constexpr (Method::kDivergenceStage)
      stages_("divergence", [&] { method_.divergence(exec, step); });

    stages_("pressure", [&] { stats_ = method_.pressure(exec, step); });

    stages_("integration", [&] {
      if (step.boundary_force) method_.add_reactions(exec, step);
      if constexpr (Method::kOwnIntegration) {
        method_.integrate(exec, step, raw<Vec3>(particles_.velocity),
                          raw<Vec3>(particles_.position));
      } else {
        run<Backend>(
            step.owned,
            SymplecticEulerStage{step.other_acceleration, step.pressure_acceleration, dt,
                                 raw<Vec3>(particles_.velocity), raw<Vec3>(particles_.position)});
      }
    });
  }

  FluidSetup setup_;
  Method method_;
  DeviceParticles<Backend> particles_, last_good_;
  DeviceGrid<Backend> grid_;
  DeviceNeighbourList<Backend> fluid_list_, boundary_list_, reaction_list_;
  DeviceBodies<Backend> bodies_;
  vector<Vec3> boundary_force_;
  mutable vector<double> block_partials_;
  StageRunner stages_;
  int threads_;
  std::size_t counts_[kParticleTypeCount] = {};
  SolverStats stats_;
  vector<Real> rest_density_, viscosity_, boundary_viscosity_;
  vector<std::uint8_t> owns_;
  vector<std::uint32_t> owned_;
  vector<Vec3> fluid_gradient_, boundary_gradient_, other_acceleration_, pressure_acceleration_;
  vector<Real>* density_ = nullptr;
  vector<Real>* pressure_ = nullptr;
};

}  // namespace upf::device
