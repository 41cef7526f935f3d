// How a solver's step runs its named stages (DESIGN.md, "Stages, executors and backends").
//
// A solver declares its stages once (Solver::stages()); its step hands each piece of work to the
// world's runner under one of those names. The runner times every stage the same way, so the
// metrics columns are the declared list, in every step and for every solver alike, and a stage
// that runs several times in a step (DEM sub-steps) adds up. The runner is also where the world
// does what a stage boundary needs beyond timing: it is the one place a device synchronisation or
// a halo refresh before a stage belongs. The work itself launches particle stages on the executor.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "framework/core/stopwatch.h"

namespace upf {

class StageRunner {
 public:
  StageRunner() = default;
  explicit StageRunner(std::vector<std::string> names)
      : names_(std::move(names)), ms_(names_.size(), 0.0) {}

  // Runs work() as stage `name`, adding its wall time. A name the solver did not declare is a
  // programming error.
  template <class Work>
  void operator()(std::string_view name, Work&& work) {
    const std::size_t k = index_of(name);
    const Stopwatch watch;
    work();
    ms_[k] += watch.elapsed_ms();
  }

  // Starts a step: every stage at zero.
  void clear() { ms_.assign(names_.size(), 0.0); }
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<double>& ms() const { return ms_; }

 private:
  std::size_t index_of(std::string_view name) const {
    for (std::size_t k = 0; k < names_.size(); ++k)
      if (names_[k] == name) return k;
    throw std::logic_error("stage '" + std::string(name) + "' was not declared by its solver");
  }

  std::vector<std::string> names_;
  std::vector<double> ms_;
};

}  // namespace upf
