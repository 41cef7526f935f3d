#include "solvers/sources/sink.h"

#include <vector>

#include "framework/core/vec3_eigen.h"
#include "framework/executors/rank_collectives.h"
#include "framework/particles/particles.h"
#include "solvers/sources/emitter.h"

namespace upf {

bool Sink::contains(const Eigen::Vector3d& x) const {
  if (desc_.box)
    return (x.array() >= desc_.box->min.array()).all() &&
           (x.array() <= desc_.box->max.array()).all();
  return (x - desc_.point).dot(desc_.normal) > 0;
}

SourceChange Sink::apply(Particles& particles, const SourceStep& step) {
  // Looked at before every step: the flags' storage is kept, and the arrays are only compacted
  // when something goes.
  SourceChange change;
  doomed_.assign(particles.size(), 0);
  std::size_t going = 0;
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.type[i] == ParticleType::Liquid && contains(to_eigen(particles.position[i]))) {
      doomed_[i] = 1;
      change.mass_removed += double(particles.mass[i]);
      ++going;
    }
  if (going > 0) change.removed = particles.remove(doomed_);
  if (reuse_into_) {
    // Every rank's emitter places the same layers: it gets back what all ranks took.
    std::int64_t taken = std::int64_t(change.removed);
    if (step.ranks) taken = step.ranks->sum(taken);
    reuse_into_->give_back(std::uint64_t(taken));
  }
  if (outflow_) outflow_->apply(particles, step.ranks);
  return change;
}

}  // namespace upf
