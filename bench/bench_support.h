// What the benchmarks share: the median of several runs, and timing a world's steps by stage.
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "framework/world/world.h"

namespace upf::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// `steps` steps of `world`: their summed wall time, solver iterations and time by stage
// (StepReport's figures, "neighbours" included).
struct StepTimes {
  double wall_ms = 0, iterations = 0;
  std::map<std::string, double> stage_ms;
};

inline StepTimes time_steps(World& world, int steps) {
  StepTimes t;
  for (int s = 0; s < steps; ++s) {
    world.step(world.next_time_step());
    const auto& rep = world.last_step();
    t.wall_ms += rep.total_ms;
    t.iterations += rep.solver.iterations;
    t.stage_ms["neighbours"] += rep.neighbour_ms;
    for (const auto& [name, ms] : rep.stage_ms) t.stage_ms[name] += ms;
  }
  return t;
}

}  // namespace upf::bench
