// Whatever adds or removes particles between steps: emitters pour liquid in, sinks and outlets
// take it out (DESIGN.md, "Particles that come and go"). The world calls every source before
// each step, and nowhere else, so a step always sees a fixed set. New particles are appended
// with ids that never repeat (Particles::add); removal keeps the survivors' relative order
// (Particles::remove). So neighbour order stays a function of positions and ids, and every
// determinism guarantee holds unchanged. Every layer reacts to "the count changed" as it does to
// an MPI migration: solver fields live in Particles and follow it, the grid is rebuilt every
// step, a device pipeline gets the particles again (World::apply_sources).
#pragma once

#include <cstddef>
#include <string_view>

namespace upf {

class Particles;
class RankCollectives;
class StateWriter;
class StateReader;

// The step a source acts before: it starts at `time` and lasts `dt`. `ranks`: the other MPI
// ranks' collectives when the world is split (null on one rank); every rank calls every source
// before every step where one may change, so a source may sum over ranks (exactly, in integers).
struct SourceStep {
  double time = 0, dt = 0;
  const RankCollectives* ranks = nullptr;
};

// What a source did before one step, for the metrics.
struct SourceChange {
  std::size_t added = 0, removed = 0;
  double mass_added = 0, mass_removed = 0;  // kg
};

class ParticleSource {
 public:
  virtual ~ParticleSource() = default;
  virtual std::string_view name() const = 0;
  // Whether apply() would change anything before the step from `time` of length `dt` without
  // reading the particles (an emitter knows from its clock): false lets a device pipeline keep
  // its particles where they are. Sinks, which must look, answer true.
  virtual bool may_change(double time, double dt) const = 0;
  // Before the step: adds or removes particles, or sets their velocities.
  virtual SourceChange apply(Particles& particles, const SourceStep& step) = 0;
  // Checkpoints: the source's own state (an emitter's clock and counts).
  virtual void save_state(StateWriter&) const {}
  virtual void restore_state(StateReader&) {}
};

}  // namespace upf
