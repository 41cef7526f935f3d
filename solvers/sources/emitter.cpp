#include "solvers/sources/emitter.h"

#include <algorithm>
#include <cmath>

#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/core/vec3_eigen.h"

namespace upf {

Emitter::Emitter(EmitterDesc desc) : desc_(std::move(desc)) {}

std::uint64_t Emitter::layers_due(double travelled) const {
  if (!(travelled > 0)) return 0;
  const double due = std::floor(travelled / desc_.spacing) + 1;
  return due >= double(desc_.max_layers) ? desc_.max_layers : std::uint64_t(due);
}

bool Emitter::may_change(double time, double /*dt*/) const {
  // While it flows the buffer's velocities are set before every step.
  return (desc_.buffer > 0 && desc_.speed.at(time) > 0 && layers_ > 0) ||
         layers_due(travelled_ + desc_.speed.distance(clock_, time)) > layers_;
}

bool Emitter::in_buffer(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d r = x - desc_.center;
  const double along = r.dot(desc_.direction);
  // Half a spacing of slack around the lattice's reach, and behind the opening.
  const double slack = 0.5 * desc_.spacing;
  if (along < -slack || along > desc_.buffer) return false;
  const double u = r.dot(desc_.width), v = r.dot(desc_.height);
  if (desc_.circle) return u * u + v * v <= (desc_.radius + slack) * (desc_.radius + slack);
  return std::abs(u) <= desc_.half_width + slack && std::abs(v) <= desc_.half_height + slack;
}

SourceChange Emitter::apply(Particles& particles, double time, double /*dt*/) {
  travelled_ += desc_.speed.distance(clock_, time);
  clock_ = time;
  const std::uint64_t due = layers_due(travelled_);
  SourceChange change;
  const double speed = desc_.speed.at(time);
  if (desc_.buffer > 0 && speed > 0) {
    const Vec3 imposed = to_vec3(desc_.direction * speed);
    for (std::size_t i = 0; i < particles.size(); ++i)
      if (particles.type[i] == ParticleType::Liquid && particles.material[i] == desc_.material &&
          in_buffer(to_eigen(particles.position[i])))
        particles.velocity[i] = imposed;
  }
  if (due <= layers_) return change;
  const std::uint64_t per_layer = desc_.opening.size();
  if (due > desc_.budget_layers)
    throw InputError(desc_.budget_where,
                     "emitter '" + desc_.name + "' reached its max_particles (" +
                         std::to_string(desc_.budget_layers * per_layer) + " particles, " +
                         std::to_string(desc_.budget_layers) +
                         " layers) at t = " + std::to_string(time) +
                         " s: the run stops here, the frames written so far are kept. Raise "
                         "max_particles, or set at_limit \"close\" to stop the emitter instead");
  const std::uint64_t new_ids = (due - layers_) * per_layer;
  if (new_ids > std::uint64_t(std::numeric_limits<ParticleId>::max() - particles.id_bound()))
    throw InputError(desc_.name,
                     "the particle ids are used up (2^32 particles emitted): the "
                     "run cannot add more");
  const Vec3 velocity = to_vec3(desc_.direction * speed);
  for (std::uint64_t k = layers_; k < due; ++k) {
    // Layer k entered when the inflow had travelled k h: it has moved on by the rest since.
    const Eigen::Vector3d front =
        desc_.center + desc_.direction * (travelled_ - double(k) * desc_.spacing);
    for (const Eigen::Vector3d& offset : desc_.opening)
      particles.add(to_vec3(front + offset), velocity, desc_.particle_mass, ParticleType::Liquid,
                    desc_.material);
  }
  change.added = std::size_t(new_ids);
  change.mass_added = double(new_ids) * double(desc_.particle_mass);
  layers_ = due;
  return change;
}

void Emitter::save_state(StateWriter& out) const {
  out.put(clock_);
  out.put(travelled_);
  out.put(layers_);
}

void Emitter::restore_state(StateReader& in) {
  const auto clock = in.get<double>();
  const auto travelled = in.get<double>();
  const auto layers = in.get<std::uint64_t>();
  in.expect(std::isfinite(clock) && std::isfinite(travelled) && travelled >= 0 &&
                layers <= layers_due(travelled),
            "the emitter's clock (" + desc_.name + ")");
  clock_ = clock;
  travelled_ = travelled;
  layers_ = layers;
}

}  // namespace upf
