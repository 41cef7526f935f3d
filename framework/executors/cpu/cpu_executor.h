// The CPU executor: runs per-particle stages (particle_stage.h) over particle ranges with OpenMP,
// and the reductions solvers need, so no solver writes its own parallel loop.
//
// The thread count lives in the executor, not in OpenMP's process-wide setting, so several worlds
// with different thread counts can live in one process. Work is split statically and every stage
// writes only its own particle, so results do not depend on the count. Every reduction here is
// order-independent (max, exact fixed-point sums, the smallest id), so it too gives the same bits
// for any thread count.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "framework/core/fixed_point_term.h"
#include "framework/executors/particle_stage.h"
#include "framework/executors/rank_collectives.h"

namespace upf {

class CpuExecutor {
 public:
  // threads <= 0 means "what OpenMP would pick".
  explicit CpuExecutor(int threads = 0);

  int threads() const { return threads_; }
  // Between stages only (a run on a busy machine, thread_share_watch.h): no result depends on it.
  void set_threads(int threads) { threads_ = threads > 0 ? threads : 1; }

  // A world split over ranks attaches its domain: reductions are then global and every stage is
  // followed by a ghost refresh (rank_collectives.h). Null: one rank.
  void attach(const RankCollectives* collectives) { collectives_ = collectives; }
  const RankCollectives* collectives() const { return collectives_; }
  // How many particles `local` counts over all ranks (an average's denominator).
  std::size_t total(std::size_t local) const {
    return collectives_ ? std::size_t(collectives_->sum(std::int64_t(local))) : local;
  }

  // stage(i) for every i in `range`, split statically.
  template <ParticleStage Stage>
  void run(ParticleRange range, const Stage& stage) const {
    const std::int64_t count = static_cast<std::int64_t>(range.size);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::int64_t k = 0; k < count; ++k) stage(range[std::size_t(k)]);
    if (collectives_) collectives_->refresh_ghosts();
  }

  // Like run, without the ghost refresh: for a stage whose outputs no particle but its own reads
  // before a later stage refreshes the ghosts (DEM's contact forces, read back by their own
  // grains). On one rank it is run.
  template <ParticleStage Stage>
  void run_unshared(ParticleRange range, const Stage& stage) const {
    const std::int64_t count = static_cast<std::int64_t>(range.size);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::int64_t k = 0; k < count; ++k) stage(range[std::size_t(k)]);
  }

  // Like run, but hands out small chunks dynamically: for uneven work such as per-cell
  // neighbour gathering.
  template <ParticleStage Stage>
  void run_dynamic(ParticleRange range, const Stage& stage) const {
    const std::int64_t count = static_cast<std::int64_t>(range.size);
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads_)
    for (std::int64_t k = 0; k < count; ++k) stage(range[std::size_t(k)]);
    if (collectives_) collectives_->refresh_ghosts();
  }

  // The largest value(i) over `range`, and `floor` when that is larger (or the range empty).
  template <ParticleValue Value>
  Real max_of(ParticleRange range, const Value& value, Real floor = 0) const {
    const std::int64_t count = static_cast<std::int64_t>(range.size);
    Real best = floor;
#pragma omp parallel for schedule(static) reduction(max : best) num_threads(threads_)
    for (std::int64_t k = 0; k < count; ++k) {
      const Real v = Real(value(range[std::size_t(k)]));
      if (v > best) best = v;
    }
    return collectives_ ? Real(collectives_->max(double(best))) : best;
  }

  // Sum of value(i) over `range`, exact in fixed point with `fraction_bits` bits after the binary
  // point, so any order of additions gives the same bits: for sums that steer control flow (the
  // PCISPH stopping test). A term beyond fixed_point_term_limit (or NaN) saturates there.
  template <ParticleValue Value>
  double fixed_point_sum(ParticleRange range, const Value& value, int fraction_bits = 32) const {
    const double scale = std::ldexp(1.0, fraction_bits);
    const double limit = fixed_point_term_limit(range.size);
    const std::int64_t count = static_cast<std::int64_t>(range.size);
    std::int64_t total = 0;
#pragma omp parallel for schedule(static) reduction(+ : total) num_threads(threads_)
    for (std::int64_t k = 0; k < count; ++k)
      total += fixed_point_term(double(value(range[std::size_t(k)])), scale, limit);
    if (collectives_) total = collectives_->sum(total);
    return double(total) / scale;
  }

  // The index of the particle with the smallest id among those in [0, n) where `holds` is true, or
  // n when there is none: a report that names "the first bad particle" the same for any thread
  // count and any memory order.
  template <ParticlePredicate Predicate>
  std::size_t first_by_id(std::size_t n, const std::uint32_t* id, const Predicate& holds) const;

  // f(i) for i in [0, n): for the framework's loops over cells, blocks and sort keys, which are
  // not particle stages. Solvers use run().
  template <class Function>
  void for_each_index(std::size_t n, Function&& f) const {
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::int64_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
  }

 private:
  static int thread_index();  // of the calling thread inside a parallel region

  int threads_;
  const RankCollectives* collectives_ = nullptr;
};

template <ParticlePredicate Predicate>
std::size_t CpuExecutor::first_by_id(std::size_t n, const std::uint32_t* id,
                                     const Predicate& holds) const {
  std::vector<std::size_t> best(std::size_t(threads_), n);
  const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel num_threads(threads_)
  {
    std::size_t mine = n;
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < count; ++k) {
      const std::size_t i = std::size_t(k);
      if (holds(std::uint32_t(i)) && (mine == n || id[i] < id[mine])) mine = i;
    }
    best[std::size_t(thread_index())] = mine;
  }
  std::size_t first = n;
  for (std::size_t i : best)
    if (i != n && (first == n || id[i] < id[first])) first = i;
  return first;
}

}  // namespace upf
