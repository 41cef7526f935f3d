// The solver interface: one class per method, plugged in by name through the Registry.
// A solver moves the particles of the materials that name it; it sees the whole world, so it can
// read any particle as a neighbour (that is what makes the world unified).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "framework/core/real.h"
#include "framework/solver/stage_runner.h"

namespace upf {

class World;
class Particles;
class ParticleDomain;
class StateWriter;
class StateReader;

// A table of figures a solver adds a row to per recorded step, besides its stats (DEM: the force
// of its grains on each container face). A run writes it as FILE.csv beside probes.csv, with the
// same cadence.
struct SolverTable {
  std::string file;                  // without ".csv"; unique among the scene's solvers
  std::vector<std::string> columns;  // after the time column
};

// What a solver reports after a step, for metrics and comparisons.
struct SolverStats {
  int iterations = 0;            // pressure (or constraint) iterations of the last step
  double avg_density_error = 0;  // average relative compression (rho - rho0)/rho0, >= 0
  double max_density_error = 0;
  // Implicit viscosity's conjugate gradient iterations (implicit_viscosity.h); -1: no such solve.
  int viscosity_iterations = -1;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string_view name() const = 0;
  // Creates fields, requests neighbour lists, precomputes constants. Called once before stepping.
  virtual void prepare(World& world) = 0;
  // The largest stable step for the current state (CFL, sound speed, contact time ...).
  virtual Real max_time_step(const World& world) const = 0;
  // The names of the stages step() runs, in order (stage_runner.h): the metrics columns.
  virtual std::vector<std::string> stages() const = 0;
  // Advances the solver's particles by dt, each piece of work run through `run` under one of
  // stages(); per-particle work goes to the executor as particle stages (particle_stage.h).
  virtual void step(World& world, Real dt, StageRunner& run) = 0;
  virtual SolverStats stats() const = 0;
  // After every solver's prepare and the first neighbour lists: fills the exported fields of the
  // initial state (a fluid's density) so that frame 0 shows real values. Must not change what
  // the first step computes.
  virtual void initialize_fields(World&) {}
  // The solver's tables (after prepare), and a row of each from `state`, the world's particles.
  // A row depends only on `state`'s particles and fields (with a device pipeline they are the
  // device's, downloaded), in a way that does not depend on their order. No rows when `state`
  // lacks a field they need (a last good state keeps only the exported fields).
  virtual std::vector<SolverTable> tables(const World&) const { return {}; }
  virtual std::vector<std::vector<double>> table_rows(const World&, const Particles&) const {
    return {};
  }
  // Why this solver, as set up, cannot run on a world split over MPI ranks (particle_domain.h),
  // or empty when it can; World::set_domain refuses such a scene before any step. A solver whose
  // per-particle arrays that neighbours read are fields, and whose reductions are the
  // executor's, can (docs/extending.md, "Determinism rules").
  virtual std::string cannot_split() const { return {}; }
  // Why this solver cannot run beside ghosts (a periodic domain's images, periodic_domain.h),
  // or empty when it can: its stages must leave neighbours' values to the ghost refresh after
  // each stage. World::prepare refuses a periodic scene with such a solver.
  virtual std::string cannot_hold_images() const { return {}; }
  // World::set_domain hands a solver that can split the domain it now runs on, once, before any
  // step. A solver that keeps state by particle id outside the fields (DEM's springs) sends it
  // after the particles that migrate (ParticleDomain::departed) and gathers it for checkpoints,
  // which hold the whole world.
  virtual void split_over(const ParticleDomain&) {}
  // Checkpoints (World::save_state): what the solver keeps from one step to the next outside the
  // particle fields, which the world saves itself. Stateless solvers keep the defaults.
  virtual void save_state(StateWriter&) const {}
  virtual void restore_state(StateReader&) {}
};

}  // namespace upf
