// PCISPH (Solenthaler & Pajarola 2009) on the device pipeline, for any backend: the world's step
// (World::step) and PcisphSolver::step with the solver's own stage structs, on device arrays.
//
// A step: the last good state (a device copy), reordering on the world's cadence, the device
// grid's lists (liquid -> liquid, liquid -> boundary), then the solver's three stages
// "non_pressure", "pressure" and "integration", timed like the CPU's. Every per-particle stage and
// every reduction gives the CPU executor's bits (device_primitives.h, device_grid.h), so frames of
// this pipeline equal the CPU's bit for bit (tests/device). Scenes it does not cover yet are
// refused by make_device_pipeline, never run half-way. Its inputs are plain values
// (pcisph_setup.h): no world header reaches nvcc.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <thrust/copy.h>
#include <thrust/sort.h>

#include "device/device_grid.h"
#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/pcisph_setup.h"
#include "framework/core/stopwatch.h"
#include "framework/particles/kinetic_energy.h"
#include "framework/solver/stage_runner.h"
#include "framework/world/device_pipeline.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/pcisph/pcisph_kernels.h"

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

// The compression of the k-th owned particle into out[k] (StoppingError's percentiles).
struct ListedCompressionStage {
  ParticleRange listed;
  CompressionValue value;
  Real* out;
  UPF_HD void operator()(std::size_t k) const { out[k] = value(listed[k]); }
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

template <class Backend>
class PcisphPipeline final : public DevicePipeline {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  explicit PcisphPipeline(PcisphSetup setup)
      : setup_(std::move(setup)),
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
    predicted_density_ = &particles_.scalar_array(setup_.predicted_density);
    predicted_position_ = &particles_.vector_array(setup_.predicted_position);
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
    vector<double> partial(blocks);
    for_each_index<Backend>(
        blocks, pipeline_detail::BlockSumStage<KineticEnergyValue>{
                    KineticEnergyValue{raw<Real>(particles_.mass), raw<Vec3>(particles_.velocity)},
                    n, raw<double>(partial)});
    // The blocks in order, on the host, as block_sum adds them.
    double total = 0;
    for (double p : std::vector<double>(partial.begin(), partial.end())) total += p;
    return total;
  }

  std::size_t count(ParticleType t) const override { return counts_[int(t)]; }

  std::size_t first_broken_particle(double max_speed) const override {
    const typename Backend::ThreadScope threads(threads_);
    return first_by_id<Backend>(
        particles_.size(), raw<ParticleId>(particles_.id),
        pipeline_detail::BrokenParticle{raw<Vec3>(particles_.position),
                                        raw<Vec3>(particles_.velocity), max_speed * max_speed});
  }

  void step(std::uint64_t step_count, double dt, StepReport& report) override {
    const typename Backend::ThreadScope threads(threads_);
    particles_.snapshot_into(last_good_);
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

  // StoppingError on the device: the same value for every percentile choice.
  double stopping_error(ParticleRange owned, const CompressionValue& value) {
    const double percentile = setup_.stop_percentile;
    if (owned.size == 0) return 0.0;
    if (percentile <= 0) return fixed_point_sum<Backend>(owned, value) / double(owned.size);
    if (percentile >= 100) return double(max_of<Backend>(owned, value));
    compressions_.resize(owned.size);
    for_each_index<Backend>(owned.size, pipeline_detail::ListedCompressionStage{
                                            owned, value, raw<Real>(compressions_)});
    thrust::sort(Backend::policy(), compressions_.begin(), compressions_.end());
    const auto rank =
        std::size_t(std::max(1.0, std::ceil(percentile / 100.0 * double(owned.size)))) - 1;
    return double(compressions_[rank]);
  }

  // PcisphSolver::step and FluidSolverState's shared stages.
  void solver_step(Real dt) {
    const std::size_t n = particles_.size();
    Real* density = raw<Real>(*density_);
    Real* pressure = raw<Real>(*pressure_);
    Vec3* x_star = raw<Vec3>(*predicted_position_);
    Real* rho_star = raw<Real>(*predicted_density_);
    FluidView f;
    ParticleRange owned;
    stats_ = SolverStats{};

    stages_("non_pressure", [&] {
      owned = rebuild_owned();
      fluid_gradient_.resize(fluid_list_.total());
      boundary_gradient_.resize(n);
      other_acceleration_.resize(n);
      pressure_acceleration_.resize(n);
      f = fluid_view();
      run<Backend>(owned, DensityAndGradientsStage{f, raw<Vec3>(fluid_gradient_),
                                                   raw<Vec3>(boundary_gradient_), density});
      run<Backend>(owned, GravityAndViscosityStage{f, density, raw<Vec3>(fluid_gradient_),
                                                   setup_.gravity, raw<Vec3>(other_acceleration_)});
      run<Backend>(owned, ClearPressureStage{pressure, raw<Vec3>(pressure_acceleration_)});
    });

    stages_("pressure", [&] {
      Vec3* a_p = raw<Vec3>(pressure_acceleration_);
      run<Backend>(all_particles(n), PredictUnownedStage{f, owned_materials(), dt, x_star});
      const Real delta = Real(setup_.delta_scale / (double(dt) * double(dt)));
      const PcisphPredictStage predict{f, raw<Vec3>(other_acceleration_), a_p, dt, x_star};
      const PcisphCorrectPressureStage correct{f, x_star, delta, rho_star, pressure};
      const PcisphPressureAccelerationStage accelerate{f, pressure, raw<Vec3>(fluid_gradient_),
                                                       raw<Vec3>(boundary_gradient_), a_p};
      const CompressionValue compression{f.rest_density, f.material, rho_star};
      double error = 0;
      int iteration = 0;
      while (iteration < setup_.max_iterations) {
        run<Backend>(owned, predict);
        run<Backend>(owned, correct);
        error = stopping_error(owned, compression);
        run<Backend>(owned, accelerate);
        ++iteration;
        if (iteration >= setup_.min_iterations && error <= setup_.eta) break;
      }
      stats_.iterations = iteration;
      stats_.avg_density_error =
          setup_.stop_percentile <= 0 || owned.size == 0
              ? error
              : fixed_point_sum<Backend>(owned, compression) / double(owned.size);
      stats_.max_density_error = owned.size ? double(max_of<Backend>(owned, compression)) : 0.0;
    });

    stages_("integration", [&] {
      run<Backend>(owned, SymplecticEulerStage{
                              raw<Vec3>(other_acceleration_), raw<Vec3>(pressure_acceleration_), dt,
                              raw<Vec3>(particles_.velocity), raw<Vec3>(particles_.position)});
    });
  }

  PcisphSetup setup_;
  DeviceParticles<Backend> particles_, last_good_;
  DeviceGrid<Backend> grid_;
  DeviceNeighbourList<Backend> fluid_list_, boundary_list_;
  StageRunner stages_;
  int threads_;
  std::size_t counts_[kParticleTypeCount] = {};
  SolverStats stats_;
  vector<Real> rest_density_, viscosity_, boundary_viscosity_;
  vector<std::uint8_t> owns_;
  vector<std::uint32_t> owned_;
  vector<Vec3> fluid_gradient_, boundary_gradient_, other_acceleration_, pressure_acceleration_;
  vector<Real> compressions_;
  vector<Real>* density_ = nullptr;
  vector<Real>* pressure_ = nullptr;
  vector<Real>* predicted_density_ = nullptr;
  vector<Vec3>* predicted_position_ = nullptr;
};

}  // namespace upf::device
