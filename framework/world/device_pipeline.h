// What the world needs of a device pipeline (DESIGN.md, "Stages, executors and backends"): a
// mirror of its particles in another memory that steps there. The world keeps time, step count,
// solvers' time-step limits and errors; the pipeline keeps the particles between frames. Which
// copy is current is the world's business (World::particles downloads when the device's is).
//
// Implementations live in device/ (one source, a CUDA and a Thrust-OpenMP instantiation). This
// header is C++17 and needs no other world header, so nvcc builds them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "framework/core/particle_type.h"
#include "framework/core/vec3.h"
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
  // One step of dt on the device, as World::step does it on the CPU: last good state, reordering
  // on the world's cadence (it is the world's step number `step_count`), neighbour lists, the
  // solvers' stages. Fills `report`'s stage times and solver statistics.
  virtual void step(std::uint64_t step_count, double dt, StepReport& report) = 0;
  // The device's particles into `particles` (every array and field, in the device's order).
  virtual void download(Particles& particles) const = 0;
  // The state before the last step, as Particles::snapshot_into leaves it.
  virtual void download_last_good(Particles& into) const = 0;
  // max |v|^2 over liquid particles, for the solvers' CFL limits.
  virtual Real max_liquid_speed_squared() const = 0;
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
