// One solver's step inside a device pipeline (solver_pipeline.h), and what all of a pipeline's
// solvers share: the particles, the neighbour lists, the coupling arrays (coupling.h) and the
// world's settings. A part asks for its lists when it is made, binds its fields after every
// upload, and steps on the shared state in the world's solver order, timing its own stages as
// the world's StageRunner does.
#pragma once

#include <cstddef>
#include <cstdint>

#include <thrust/copy.h>
#include <thrust/iterator/counting_iterator.h>

#include "device/device_lists.h"
#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/pipeline_setup.h"
#include "framework/solver/solver.h"
#include "framework/solver/stage_runner.h"
#include "solvers/fluid/owned_particles.h"

namespace upf::device {

template <class Backend>
struct PipelineState {
  template <class T>
  using vector = typename Backend::template vector<T>;

  explicit PipelineState(WorldSetup settings) : world(settings), lists(settings.support_radius) {}

  WorldSetup world;
  DeviceParticles<Backend> particles;
  // The particles [0, owned) are the world's; periodic images follow them during a step, and
  // `ghosts` (null without) refreshes them after every shared stage (DeviceExecutor).
  std::size_t owned = 0;
  const DeviceGhosts* ghosts = nullptr;
  DeviceLists<Backend> lists;
  // The coupling arrays, sized and zeroed at each step's start when active; empty otherwise.
  vector<Vec3> boundary_force, liquid_force;
  ParticleId id_bound = 0;  // Particles::id_bound of the uploaded particles

  Vec3* boundary_force_or_null() {
    return boundary_force.empty() ? nullptr : raw<Vec3>(boundary_force);
  }
  Vec3* liquid_force_or_null() { return liquid_force.empty() ? nullptr : raw<Vec3>(liquid_force); }
};

namespace part_detail {
struct OwnedIndex {
  const MaterialId* material;
  OwnedMaterials owns;
  UPF_HD bool operator()(std::uint32_t i) const { return owns(material[i]); }
};
struct TypeIs {
  const ParticleType* type;
  ParticleType of;
  UPF_HD bool operator()(std::uint32_t i) const { return type[i] == of; }
};
}  // namespace part_detail

// The indices i < n with keep(i), in index order (OwnedParticles::rebuild), into `out`.
template <class Backend, class Keep>
ParticleRange indices_where(std::size_t n, const Keep& keep,
                            typename Backend::template vector<std::uint32_t>& out) {
  out.resize(n);
  const auto last = thrust::copy_if(Backend::policy(), thrust::counting_iterator<std::uint32_t>(0),
                                    thrust::counting_iterator<std::uint32_t>(std::uint32_t(n)),
                                    out.begin(), keep);
  return {raw<std::uint32_t>(out), std::size_t(last - out.begin())};
}

template <class Backend>
class SolverPart {
 public:
  virtual ~SolverPart() = default;
  // After every upload: the part's fields in the new arrays, its state from the host's solver.
  virtual void bind(PipelineState<Backend>& state) = 0;
  // One step of dt, its stages timed in stages().
  virtual void step(PipelineState<Backend>& state, Real dt) = 0;
  virtual const StageRunner& stages() const = 0;
  virtual SolverStats stats() const = 0;
  virtual std::size_t bytes() const = 0;
  // The state kept on the device between steps into the host's solver (DEM's springs).
  virtual void download_state() const {}
};

}  // namespace upf::device
