#include "solvers/sources/emitter.h"

#include <algorithm>
#include <cmath>

#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/core/vec3_eigen.h"

namespace upf {

namespace {

constexpr std::uint64_t kNoLimit = std::numeric_limits<std::uint64_t>::max();

// The most layers a column of factor f places under a limit of `limit` layers of the mean flow:
// the limit itself when f = 1.
std::uint64_t column_limit(double f, std::uint64_t limit) {
  if (limit == kNoLimit) return kNoLimit;
  const double most = std::floor(f * double(limit - 1)) + 1;
  return most >= double(kNoLimit) ? kNoLimit : std::uint64_t(most);
}

// Layers of a column of factor f due once the inflow has travelled `travelled`, at most `cap`.
std::uint64_t column_due(double f, double travelled, double spacing, std::uint64_t cap) {
  if (!(travelled > 0) || !(f > 0)) return 0;
  const double due = std::floor(f * travelled / spacing) + 1;
  return due >= double(cap) ? cap : std::uint64_t(due);
}

}  // namespace

double particles_due(const EmitterDesc& desc, double travelled) {
  double n = 0;  // a double: an absurd pour must reach the memory check, not wrap around
  for (const Eigen::Vector3d& o : desc.opening) {
    const double f = desc.profile.factor(o);
    n += double(column_due(f, travelled, desc.spacing, column_limit(f, desc.max_layers)));
  }
  return n;
}

Emitter::Emitter(EmitterDesc desc)
    : desc_(std::move(desc)),
      column_layers_(desc_.opening.size(), 0),
      due_(desc_.opening.size(), 0) {
  factor_.reserve(desc_.opening.size());
  for (const Eigen::Vector3d& o : desc_.opening) factor_.push_back(desc_.profile.factor(o));
}

std::uint64_t Emitter::layers_due(std::size_t i, double travelled) const {
  return column_due(factor_[i], travelled, desc_.spacing,
                    column_limit(factor_[i], desc_.max_layers));
}

bool Emitter::any_due(double travelled) const {
  for (std::size_t i = 0; i < factor_.size(); ++i)
    if (layers_due(i, travelled) > column_layers_[i]) return true;
  return false;
}

bool Emitter::may_change(double time, double /*dt*/) const {
  // While it flows the buffer's velocities are set before every step.
  return (desc_.buffer > 0 && desc_.speed.at(time) > 0 && layers_ > 0) ||
         any_due(travelled_ + desc_.speed.distance(clock_, time));
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

SourceChange Emitter::apply(Particles& particles, const SourceStep& step) {
  const double time = step.time;
  travelled_ += desc_.speed.distance(clock_, time);
  clock_ = time;
  SourceChange change;
  const double speed = desc_.speed.at(time);
  if (desc_.buffer > 0 && speed > 0) {
    for (std::size_t i = 0; i < particles.size(); ++i)
      if (particles.type[i] == ParticleType::Liquid && particles.material[i] == desc_.material) {
        const Eigen::Vector3d x = to_eigen(particles.position[i]);
        if (in_buffer(x))
          particles.velocity[i] =
              to_vec3(desc_.direction * (speed * desc_.profile.factor(x - desc_.center)));
      }
  }
  std::vector<std::uint64_t>& due = due_;  // kept between steps: no allocation per step
  std::uint64_t first = kNoLimit, last = 0, new_ids = 0;
  for (std::size_t i = 0; i < factor_.size(); ++i) {
    due[i] = layers_due(i, travelled_);
    if (due[i] <= column_layers_[i]) continue;
    if (due[i] > column_limit(factor_[i], desc_.budget_layers))
      throw InputError(desc_.budget_where,
                       "emitter '" + desc_.name + "' reached its max_particles (" +
                           std::to_string(desc_.budget_layers * desc_.opening.size()) +
                           " particles, " + std::to_string(desc_.budget_layers) +
                           " layers) at t = " + std::to_string(time) +
                           " s: the run stops here, the frames written so far are kept. Raise "
                           "max_particles, or set at_limit \"close\" to stop the emitter instead");
    first = std::min(first, column_layers_[i]);
    last = std::max(last, due[i]);
    new_ids += due[i] - column_layers_[i];
  }
  if (new_ids == 0) return change;
  if (new_ids > std::uint64_t(std::numeric_limits<ParticleId>::max() - particles.id_bound()))
    throw InputError(desc_.name,
                     "the particle ids are used up (2^32 particles emitted): the "
                     "run cannot add more");
  // With live_limit, what fits: the particles of its own in the scene (made less given back) stay
  // within it, and the layers due while it is full are skipped, as SPlisHSPlasH's emitter with
  // particle reuse emits only the particles it has.
  const std::uint64_t live = created_ > returned_ ? created_ - returned_ : 0;
  std::uint64_t room = desc_.live_limit == kNoLimit ? new_ids
                       : live < desc_.live_limit    ? desc_.live_limit - live
                                                    : 0;
  std::uint64_t placed = 0;
  // Layer by layer, each in lattice order: a uniform profile places whole layers as they come.
  for (std::uint64_t k = first; k < last && placed < room; ++k)
    for (std::size_t i = 0; i < factor_.size() && placed < room; ++i) {
      if (k < column_layers_[i] || k >= due[i]) continue;
      ++placed;
      // Layer k of this column entered when it had travelled k h: it has moved on by the rest.
      const double f = factor_[i];
      const Eigen::Vector3d front =
          desc_.center + desc_.direction * (f * travelled_ - double(k) * desc_.spacing);
      particles.add(to_vec3(front + desc_.opening[i]), to_vec3(desc_.direction * (speed * f)),
                    desc_.particle_mass, ParticleType::Liquid, desc_.material);
    }
  for (std::size_t i = 0; i < factor_.size(); ++i) {
    column_layers_[i] = std::max(column_layers_[i], due[i]);
    layers_ = std::max(layers_, column_layers_[i]);
  }
  created_ += placed;
  change.added = std::size_t(placed);
  change.mass_added = double(placed) * double(desc_.particle_mass);
  return change;
}

void Emitter::save_state(StateWriter& out) const {
  out.put(clock_);
  out.put(travelled_);
  out.put(layers_);
  if (desc_.live_limit != kNoLimit) {
    out.put(created_);
    out.put(returned_);
  }
}

void Emitter::restore_state(StateReader& in) {
  const auto clock = in.get<double>();
  const auto travelled = in.get<double>();
  const auto layers = in.get<std::uint64_t>();
  // Every column has placed the layers due at `travelled` (apply() places all that are due).
  std::uint64_t most = 0;
  if (std::isfinite(travelled) && travelled >= 0)
    for (std::size_t i = 0; i < factor_.size(); ++i)
      most = std::max(most, layers_due(i, travelled));
  in.expect(std::isfinite(clock) && std::isfinite(travelled) && travelled >= 0 && layers == most,
            "the emitter's clock (" + desc_.name + ")");
  clock_ = clock;
  travelled_ = travelled;
  layers_ = layers;
  for (std::size_t i = 0; i < factor_.size(); ++i) column_layers_[i] = layers_due(i, travelled);
  if (desc_.live_limit != kNoLimit) {
    created_ = in.get<std::uint64_t>();
    returned_ = in.get<std::uint64_t>();
  }
}

}  // namespace upf
