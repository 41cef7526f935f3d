// The CPU executor: runs per-particle functions over index ranges with OpenMP.
//
// The thread count lives in the executor, not in OpenMP's process-wide setting, so several worlds
// with different thread counts can live in one process. Work is split statically and every
// per-particle function only writes its own particle, so results do not depend on the count.
#pragma once

#include <cstddef>
#include <cstdint>

namespace upf {

class CpuExecutor {
 public:
  // threads <= 0 means "what OpenMP would pick".
  explicit CpuExecutor(int threads = 0);

  int threads() const { return threads_; }

  template <class Function>
  void for_each(std::size_t n, Function&& f) const {
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::int64_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
  }

  // Like for_each, but hands out small chunks dynamically: for uneven work such as per-cell
  // neighbour gathering. Still deterministic because each index writes only its own outputs.
  template <class Function>
  void for_each_dynamic(std::size_t n, Function&& f) const {
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads_)
    for (std::int64_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
  }

 private:
  int threads_;
};

}  // namespace upf
