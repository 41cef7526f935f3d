// What the world needs of a device pipeline (DESIGN.md, "Stages, executors and backends"): a
// mirror of its particles in another memory that steps there. The world keeps time, step count,
// solvers' time-step limits and errors; the pipeline keeps the particles between frames. Which
// copy is current is the world's business (World::particles downloads when the device's is).
//
// Body systems (body_system.h) keep their bodies on the host and do their per-particle work through
// the pipeline (body_particle_stages.h): poses go down, six numbers per body and the guard's hits
// come back.
//
// Implementations live in device/ (one source, a CUDA and a Thrust-OpenMP instantiation). This
// header is C++17 and needs no other world header, so nvcc builds them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/particle_type.h"
#include "framework/core/vec3.h"
#include "framework/world/body_particle_stages.h"
#include "framework/world/step_report.h"

namespace upf {

class Particles;

class DevicePipeline {
 public:
  virtual ~DevicePipeline() = default;

  // "omp" or "cuda": what --device named.
  virtual std::string_view name() const = 0;
  // Copies every particle array and field of a prepared world to the device.
  virtual void upload(const Particles& particles) = 0;
  // The state at a step's start, kept for download_last_good; before the bodies move.
  virtual void save_last_good() = 0;
  // One step of dt on the device, as World::step does it on the CPU after the bodies have placed
  // their particles: reordering on the world's cadence (it is the world's step number
  // `step_count`), neighbour lists, the reactions on bodies zeroed, the solvers' stages. Fills
  // `report`'s stage times and solver statistics.
  virtual void step(std::uint64_t step_count, double dt, StepReport& report) = 0;
  // Bodies. PlaceBodyParticlesStage with `poses` per body id and the body-frame positions in
  // the vector field `local_field`.
  virtual void place_body_particles(const std::vector<BodyPose>& poses,
                                    const std::string& local_field) = 0;
  // Per body id of `origins`: the sum of the last step's fluid reactions on its rigid particles
  // (CouplingArray::BoundaryForce on the CPU) and their torques about origins[body].
  virtual void body_wrenches(const std::vector<Vec3d>& origins,
                             std::vector<BodyWrench>& wrenches) = 0;
  // SurfaceGuardStage over the liquid particles, with the step's liquid -> boundary list; `meshes`
  // per body id (null: not guarded) are the same at every call. `hits` in particle-id order.
  virtual void guard_body_surfaces(const std::vector<BodyPose>& poses,
                                   const std::vector<const MeshParityData*>& meshes,
                                   double layer_depth, double clearance,
                                   const std::string& local_field, const std::string& normal_field,
                                   std::vector<SurfaceHit>& hits) = 0;

  // The device's particles into `particles` (every array and field, in the device's order).
  virtual void download(Particles& particles) const = 0;
  // The state before the last step, as Particles::snapshot_into leaves it.
  virtual void download_last_good(Particles& into) const = 0;
  // max |v|^2 over liquid particles, for the solvers' CFL limits.
  virtual Real max_liquid_speed_squared() const = 0;
  // max |v|^2 over the particles of `type` and of the materials m with materials[m] != 0.
  virtual Real max_speed_squared(ParticleType type,
                                 const std::vector<std::uint8_t>& materials) const = 0;
  // The solvers' state that lives on the device between steps (DEM's springs) into the host's
  // solvers, which take it back at the next upload: with download, for checkpoints.
  virtual void download_solver_states() const = 0;
  // The metrics' kinetic energy, the same bits as on the host (kinetic_energy.h).
  virtual double kinetic_energy() const = 0;
  // Particles of `type` (types do not change while the device steps).
  virtual std::size_t count(ParticleType type) const = 0;
  // Device memory its buffers hold now, in bytes.
  virtual std::size_t device_bytes() const = 0;
  // The index of the first particle (by id) with a non-finite position or velocity or a speed
  // above max_speed, or the particle count when all are fine (World::check_stability).
  virtual std::size_t first_broken_particle(double max_speed) const = 0;
};

}  // namespace upf
