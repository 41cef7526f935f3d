// The world: particles, materials, the neighbour grid and the solvers, stepped together.
//
// World::step(dt) (DESIGN.md, "One step"):
//   1 body systems place their particles (rigid particles follow their bodies)
//   2 neighbour grid update and the neighbour lists solvers asked for; reorder every K steps
//   3 the coupling arrays are zeroed, then each solver advances its own particles, in an order
//     where every coupling array is written before it is read (coupling.h), its stages run and
//     timed by the world (stage_runner.h)
//   4 body systems sum the reactions per body and step their bodies (body_system.h)
//   5 time += dt; stability check (NaN, runaway speed)
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "framework/executors/cpu/cpu_executor.h"
#include "framework/kernels/cubic_spline.h"
#include "framework/materials/material.h"
#include "framework/neighbours/neighbour_grid.h"
#include "framework/particles/particles.h"
#include "framework/solver/solver.h"
#include "framework/world/body_system.h"
#include "framework/world/container_box.h"
#include "framework/world/coupling.h"
#include "framework/world/device_pipeline.h"
#include "framework/world/particle_domain.h"
#include "framework/world/particle_source.h"
#include "framework/world/step_report.h"
#include "framework/world/world_settings.h"

namespace upf {

class World {
 public:
  World(WorldSettings settings, int threads);

  // With a device pipeline the device holds the current particles between steps: both accessors
  // download them first, and the mutable one uploads them again before the next step.
  Particles& particles() {
    sync_host();
    device_stale_ = device_ != nullptr;
    return particles_;
  }
  const Particles& particles() const {
    sync_host();
    return particles_;
  }
  MaterialTable& materials() { return materials_; }
  const MaterialTable& materials() const { return materials_; }
  const WorldSettings& settings() const { return settings_; }
  const CpuExecutor& executor() const { return executor_; }
  // Between steps; the results are the same bits for any count (cpu_executor.h). A device
  // pipeline keeps the count it was made with.
  void set_threads(int threads) { executor_.set_threads(threads); }
  CubicSplineKernel kernel() const { return CubicSplineKernel(settings_.support_radius()); }

  // `use`: the coupling arrays it writes and reads (its SolverInfo's declaration).
  void add_solver(std::unique_ptr<Solver> solver, CouplingUse use = {});
  // In stepping order once prepare() has run.
  const std::vector<std::unique_ptr<Solver>>& solvers() const { return solvers_; }
  // The arrays that cross materials within a step (coupling.h).
  CouplingArrays& coupling() { return coupling_; }
  const CouplingArrays& coupling() const { return coupling_; }
  void add_body_system(std::unique_ptr<BodySystem> system);
  // Adds or removes particles before every step (particle_source.h: emitters, sinks).
  void add_source(std::unique_ptr<ParticleSource> source);
  const std::vector<std::unique_ptr<ParticleSource>>& sources() const { return sources_; }
  const std::vector<std::unique_ptr<BodySystem>>& body_systems() const { return bodies_; }
  void add_container(const ContainerBox& box) { containers_.push_back(box); }
  const std::vector<ContainerBox>& containers() const { return containers_; }

  // Asks for neighbour lists (query types -> target types within `radius`, at most and by
  // default the support radius), rebuilt every step. Call from Solver::prepare; returns a
  // handle for neighbours().
  int request_neighbours(TypeMask query, TypeMask target, Real radius = 0);
  const NeighbourList& neighbours(int handle) const { return lists_.at(std::size_t(handle)).list; }
  int neighbour_list_count() const { return int(lists_.size()); }
  // The radius a request got (capped at the support radius).
  Real neighbour_radius(int handle) const { return lists_.at(std::size_t(handle)).radius; }
  const NeighbourGrid& grid() const { return grid_; }

  // Steps on `pipeline` from now on (device/device_pipelines.h makes them), or on the CPU again
  // when null. Call after prepare(). Neighbour lists of the world (neighbours()) are then not
  // kept: the pipeline's solvers use its own.
  void set_device(std::unique_ptr<DevicePipeline> pipeline);
  const DevicePipeline* device() const { return device_.get(); }
  // For body systems while the device steps: their per-particle work goes through it.
  DevicePipeline* device() { return device_.get(); }
  // Splits the world over MPI ranks from now on (particle_domain.h): every rank has built and
  // prepared the same scene, and keeps its share. Call after prepare() (and after restore_state
  // when resuming); not with a device pipeline. particles() then holds this rank's particles.
  void set_domain(std::unique_ptr<ParticleDomain> domain);
  const ParticleDomain* domain() const { return domain_.get(); }
  // max |v|^2 over liquid particles, wherever they are (the solvers' CFL limits).
  Real max_liquid_speed_squared() const;
  // max |v|^2 over the particles of `type` whose material m has material_flags[m] != 0 (m below
  // material_count), wherever they are: a solver's time-step limit (DEM's list skin).
  Real max_speed_squared(ParticleType type, const std::uint8_t* material_flags,
                         std::size_t material_count) const;
  // The metrics' kinetic energy (kinetic_energy.h) and particle counts, wherever the particles
  // are (over every rank when split).
  double kinetic_energy() const;
  std::size_t count(ParticleType type) const;

  // Orders the solvers by their coupling declarations (an InputError naming the solvers when a
  // read has no writer or the declarations form a cycle), boundary volumes of frozen and rigid
  // particles (Akinci et al. 2012), every body system's prepare, then every solver's prepare.
  void prepare();

  // The next step size: the fixed dt, or the minimum over solvers clamped to [dt_min, dt_max].
  double next_time_step() const;
  // The next step towards `end`: the remaining time split into equal steps no longer than
  // next_time_step(). A short last step would distort PCISPH pressures, which scale as 1/dt^2.
  double next_time_step_until(double end) const;
  // Advances by dt. Throws InstabilityError (with the last good state kept) when it blows up.
  void step(double dt);
  // One step of next_time_step_until(stop); the step that reaches `stop` lands on it exactly
  // (time() == stop, not a sum of rounded steps), so frames fall on n / fps to the bit and the
  // steps after a stop do not depend on the rounding of the ones before.
  void step_towards(double stop);
  // The stages of a step, once prepare() has run: the metrics columns (StepReport::stage_ms).
  std::vector<std::string> stage_names() const;

  // Checkpoints: time, step count, particles, then each solver's and body system's own state.
  // restore_state runs after prepare() on a world built from the same scene; a checkpoint of
  // another scene is an InputError.
  void save_state(StateWriter& out) const;
  void restore_state(StateReader& in);

  double time() const { return time_; }
  std::uint64_t step_count() const { return step_count_; }
  const StepReport& last_step() const { return report_; }
  // The state before the last step: what to write when that step went unstable.
  const Particles& last_good() const { return last_good_; }

 private:
  struct ListRequest {
    TypeMask query, target;
    Real radius;
    NeighbourList list;
  };
  void order_solvers();
  void update_neighbours();
  void check_stability() const;
  void step_on_device(double dt);
  // Every source's changes before the step of `dt` from now, summed into `sources_done_`.
  void apply_sources(double dt);
  void check_stability_on_device();
  // Downloads the device's particles when they are newer than the host's.
  void sync_host() const;

  WorldSettings settings_;
  CpuExecutor executor_;
  // Mutable: the const accessors download the device's copy into it (sync_host).
  mutable Particles particles_;
  Particles last_good_;
  MaterialTable materials_;
  NeighbourGrid grid_;
  std::vector<ListRequest> lists_;
  std::vector<std::unique_ptr<Solver>> solvers_;
  std::vector<CouplingUse> solver_uses_;    // parallel to solvers_
  std::vector<StageRunner> stage_runners_;  // parallel to solvers_, made by prepare()
  CouplingArrays coupling_;
  std::vector<std::unique_ptr<BodySystem>> bodies_;
  std::vector<std::unique_ptr<ParticleSource>> sources_;
  SourceChange sources_done_;  // before the step being taken, for its report
  double sources_ms_ = 0;      // the time they took
  std::vector<ContainerBox> containers_;
  double time_ = 0;
  std::uint64_t step_count_ = 0;
  bool prepared_ = false;
  // The prepared scene's particles (particle_identity.h): a checkpoint must hold the same.
  std::uint64_t identity_ = 0;
  StepReport report_;
  std::unique_ptr<DevicePipeline> device_;
  std::unique_ptr<ParticleDomain> domain_;
  // domain_ is the one-process PeriodicDomain prepare() made (set_domain may replace it).
  bool periodic_images_only_ = false;
  mutable bool host_stale_ = false;  // the device's particles are newer
  bool device_stale_ = false;        // the host's particles are newer (or never uploaded)
};

}  // namespace upf
