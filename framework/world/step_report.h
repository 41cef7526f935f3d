// What one step did, for metrics. C++17 and free of the world's other headers, so the device
// pipeline (device/, built by nvcc too) fills it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "framework/solver/solver.h"
#include "framework/world/particle_source.h"

namespace upf {

struct StepReport {
  double dt = 0;
  double neighbour_ms = 0;
  double total_ms = 0;
  SolverStats solver;  // merged over solvers: max iterations, max errors
  // Wall milliseconds by stage, in World::stage_names() order: every solver's declared stages,
  // then "bodies" when there are body systems.
  std::vector<std::pair<std::string, double>> stage_ms;
  // What emitters and sinks did before the step (particle_source.h).
  SourceChange sources;
};

}  // namespace upf
