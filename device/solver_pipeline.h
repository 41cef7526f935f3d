// The device pipeline for any backend (device_backend_*.h): the world's step (World::step) on
// device arrays, with one part per solver in the world's stepping order (fluid_part.h,
// dem_part.h), so grains and liquids couple through liquid_force and bodies through
// boundary_force as on the CPU.
//
// A step: the last good state (a device copy), the bodies' placement (device_bodies.h, driven by
// the host's body system), reordering on the world's cadence, every list the parts asked for
// (device_lists.h), the coupling arrays zeroed, then each part's stages, timed like the CPU's.
// Every per-particle stage and every reduction gives the CPU executor's bits (device_primitives.h,
// device_grid.h), so frames of this pipeline equal the CPU's bit for bit (tests/device). A
// periodic world's images live on the device during a step (device_images.h). Scenes it
// does not cover are refused by make_device_pipeline, never run half-way. Its inputs are plain
// values (pipeline_setup.h): no world header reaches nvcc.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <thrust/copy.h>
#include <thrust/fill.h>

#include "device/device_bodies.h"
#include "device/device_grid.h"
#include "device/device_images.h"
#include "device/solver_part.h"
#include "framework/core/stopwatch.h"
#include "framework/particles/kinetic_energy.h"
#include "framework/particles/particle_checks.h"
#include "framework/world/device_pipeline.h"

namespace upf::device {

namespace pipeline_detail {

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

template <class Backend>
class SolverPipeline final : public DevicePipeline {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  explicit SolverPipeline(const WorldSetup& world)
      : state_(world),
        grid_(world.support_radius),
        images_(world.periodic, world.support_radius),
        threads_(world.threads) {
    // The penetration guard's list (the fluids ask for the same one).
    guard_list_ = state_.lists.request(kLiquidMask, kBoundaryMask);
    if (world.periodic.any()) state_.ghosts = &images_;
  }

  // Parts are added in the world's solver order, before the first upload; they ask for their
  // lists in their constructors (state()).
  void add(std::unique_ptr<SolverPart<Backend>> part) { parts_.push_back(std::move(part)); }
  PipelineState<Backend>& state() { return state_; }

  std::string_view name() const override { return Backend::name; }

  void upload(const Particles& particles) override {
    const typename Backend::ThreadScope threads(threads_);
    state_.particles.upload(particles);
    state_.id_bound = particles.id_bound();
    for (int t = 0; t < kParticleTypeCount; ++t) counts_[t] = particles.count(ParticleType(t));
    for (auto& part : parts_) part->bind(state_);
  }

  void download(Particles& p) const override { state_.particles.download(p); }
  void download_last_good(Particles& into) const override { last_good_.download_snapshot(into); }
  void download_solver_states() const override {
    for (const auto& part : parts_) part->download_state();
  }

  Real max_liquid_speed_squared() const override {
    const typename Backend::ThreadScope threads(threads_);
    const DeviceParticles<Backend>& p = state_.particles;
    return max_of<Backend>(all_particles(p.size()),
                           LiquidSpeedSquared{raw<Vec3>(p.velocity), raw<ParticleType>(p.type)});
  }

  Real max_speed_squared(ParticleType type,
                         const std::vector<std::uint8_t>& materials) const override {
    const typename Backend::ThreadScope threads(threads_);
    speed_materials_.resize(materials.size());
    thrust::copy(materials.begin(), materials.end(), speed_materials_.begin());
    const DeviceParticles<Backend>& p = state_.particles;
    return max_of<Backend>(
        all_particles(p.size()),
        SpeedSquaredOf{raw<Vec3>(p.velocity), raw<ParticleType>(p.type),
                       raw<MaterialId>(p.material), type, raw<std::uint8_t>(speed_materials_),
                       speed_materials_.size()});
  }

  double kinetic_energy() const override {
    const typename Backend::ThreadScope threads(threads_);
    const DeviceParticles<Backend>& p = state_.particles;
    const std::size_t n = p.size();
    const std::size_t blocks = (n + kBlockSumSize - 1) / kBlockSumSize;
    block_partials_.resize(blocks);
    for_each_index<Backend>(blocks,
                            pipeline_detail::BlockSumStage<KineticEnergyValue>{
                                KineticEnergyValue{raw<Real>(p.mass), raw<Vec3>(p.velocity)}, n,
                                raw<double>(block_partials_)});
    // The blocks in order, on the host, as block_sum adds them.
    double total = 0;
    for (double b : std::vector<double>(block_partials_.begin(), block_partials_.end())) total += b;
    return total;
  }

  std::size_t count(ParticleType t) const override { return counts_[int(t)]; }

  std::size_t device_bytes() const override {
    std::size_t total = state_.particles.bytes() + last_good_.bytes() + grid_.bytes() +
                        state_.lists.bytes() + bytes_of(state_.boundary_force) +
                        bytes_of(state_.liquid_force) + bodies_.bytes() +
                        bytes_of(block_partials_) + bytes_of(speed_materials_) + images_.bytes();
    for (const auto& part : parts_) total += part->bytes();
    return total;
  }

  std::size_t first_broken_particle(double max_speed) const override {
    const typename Backend::ThreadScope threads(threads_);
    const DeviceParticles<Backend>& p = state_.particles;
    return first_by_id<Backend>(
        p.size(), raw<ParticleId>(p.id),
        BrokenParticle{raw<Vec3>(p.position), raw<Vec3>(p.velocity), max_speed * max_speed});
  }

  void save_last_good() override {
    const typename Backend::ThreadScope threads(threads_);
    state_.particles.snapshot_into(last_good_);
  }

  void place_body_particles(const std::vector<BodyPose>& poses,
                            const std::string& local_field) override {
    const typename Backend::ThreadScope threads(threads_);
    bodies_.place(state_.particles, poses, local_field);
  }

  void body_wrenches(const std::vector<Vec3d>& origins,
                     std::vector<BodyWrench>& wrenches) override {
    const typename Backend::ThreadScope threads(threads_);
    bodies_.wrenches(state_.particles, state_.boundary_force, origins, wrenches);
  }

  void guard_body_surfaces(const std::vector<BodyPose>& poses,
                           const std::vector<const MeshParityData*>& meshes, double layer_depth,
                           double clearance, const std::string& local_field,
                           const std::string& normal_field,
                           std::vector<SurfaceHit>& hits) override {
    const typename Backend::ThreadScope threads(threads_);
    bodies_.guard(state_.particles, state_.lists.view(guard_list_), poses, meshes, layer_depth,
                  clearance, local_field, normal_field, hits);
  }

  void step(std::uint64_t step_count, double dt, StepReport& report) override {
    const typename Backend::ThreadScope threads(threads_);
    const Stopwatch neighbours;
    update_neighbours(step_count);
    report.neighbour_ms = neighbours.elapsed_ms();
    reset_coupling();
    // Between steps the device holds the world's particles only, also after a failed step.
    struct DropImages {
      SolverPipeline* pipeline;
      ~DropImages() {
        if (pipeline->state_.ghosts) pipeline->images_.drop();
      }
    } drop_images{this};
    for (auto& part : parts_) {
      part->step(state_, Real(dt));
      const StageRunner& stages = part->stages();
      for (std::size_t j = 0; j < stages.names().size(); ++j)
        report.stage_ms.emplace_back(stages.names()[j], stages.ms()[j]);
      // World::step's combination of the solvers' statistics.
      const SolverStats st = part->stats();
      SolverStats& out = report.solver;
      out.iterations = out.iterations > st.iterations ? out.iterations : st.iterations;
      out.avg_density_error = out.avg_density_error > st.avg_density_error ? out.avg_density_error
                                                                           : st.avg_density_error;
      out.max_density_error = out.max_density_error > st.max_density_error ? out.max_density_error
                                                                           : st.max_density_error;
      out.viscosity_iterations = out.viscosity_iterations > st.viscosity_iterations
                                     ? out.viscosity_iterations
                                     : st.viscosity_iterations;
    }
  }

 private:
  // World::step's reordering, periodic images (PeriodicDomain::exchange) and update_neighbours.
  void update_neighbours(std::uint64_t step_count) {
    DeviceParticles<Backend>& p = state_.particles;
    state_.owned = p.size();
    const int every = state_.world.reorder_every;
    auto build = [&] {
      grid_.build(raw<Vec3>(p.position), raw<ParticleId>(p.id), raw<ParticleType>(p.type),
                  p.size());
    };
    if (every > 0 && step_count % std::uint64_t(every) == 0) {
      build();
      p.permute(grid_.sorted_order());
    }
    if (state_.ghosts) images_.append(p, &state_.boundary_force, &state_.liquid_force);
    build();
    state_.lists.update(grid_, raw<ParticleType>(p.type), raw<BodyId>(p.body));
  }

  // CouplingArrays::reset: the active arrays sized and zeroed.
  void reset_coupling() {
    const std::size_t n = state_.particles.size();
    auto reset = [&](bool active, vector<Vec3>& a) {
      a.resize(active ? n : 0);
      thrust::fill(Backend::policy(), a.begin(), a.end(), Vec3{});
    };
    reset(state_.world.boundary_force, state_.boundary_force);
    reset(state_.world.liquid_force, state_.liquid_force);
  }

  PipelineState<Backend> state_;
  DeviceParticles<Backend> last_good_;
  DeviceGrid<Backend> grid_;
  DeviceBodies<Backend> bodies_;
  DeviceImages<Backend> images_;
  std::vector<std::unique_ptr<SolverPart<Backend>>> parts_;
  int guard_list_ = -1;
  int threads_;
  std::size_t counts_[kParticleTypeCount] = {};
  mutable vector<double> block_partials_;
  mutable vector<std::uint8_t> speed_materials_;
};

}  // namespace upf::device
