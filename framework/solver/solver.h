// The solver interface: one class per method, plugged in by name through the Registry.
// A solver moves the particles of the materials that name it; it sees the whole world, so it can
// read any particle as a neighbour (that is what makes the world unified).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "framework/core/real.h"

namespace upf {

class World;
class StateWriter;
class StateReader;

// What a solver reports after a step, for metrics and comparisons.
struct SolverStats {
  int iterations = 0;            // pressure (or constraint) iterations of the last step
  double avg_density_error = 0;  // average relative compression (rho - rho0)/rho0, >= 0
  double max_density_error = 0;
  std::vector<std::pair<std::string, double>> stage_ms;  // wall milliseconds by stage
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string_view name() const = 0;
  // Creates fields, requests neighbour lists, precomputes constants. Called once before stepping.
  virtual void prepare(World& world) = 0;
  // The largest stable step for the current state (CFL, sound speed, contact time ...).
  virtual Real max_time_step(const World& world) const = 0;
  virtual void step(World& world, Real dt) = 0;
  virtual SolverStats stats() const = 0;
  // Checkpoints (World::save_state): what the solver keeps from one step to the next outside the
  // particle fields, which the world saves itself. Stateless solvers keep the defaults.
  virtual void save_state(StateWriter&) const {}
  virtual void restore_state(StateReader&) {}
};

}  // namespace upf
