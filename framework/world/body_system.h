// Bodies in the particle world: whatever owns boundary particles that move as a whole (rigid
// bodies, kinematic obstacles). The world calls it around the solvers (DESIGN.md, "One step"):
//
//   1 place_particles: the system's particles follow their bodies, x = X + R r0,
//     v = V + w x (x - X), before the neighbour grid is built;
//   3 the solvers run; fluid and granular solvers add their reactions on boundary particles into
//     the world's coupling array CouplingArray::BoundaryForce (Akinci et al. 2012, eq. 11);
//   4 advance: per body, the reactions are summed into a force and a torque and the bodies step.
//
// The framework only calls this interface; coupling/ implements it with Bullet.
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/real.h"
#include "framework/output/mesh_vtp_writer.h"

namespace upf {

class World;
class StateWriter;
class StateReader;

class BodySystem {
 public:
  virtual ~BodySystem() = default;
  virtual std::string_view name() const = 0;
  // Before the solvers' prepare: boundary volumes of the system's particles, fields it needs.
  virtual void prepare(World& world) = 0;
  // Step 1: sets positions and velocities of the system's particles for a step of dt.
  virtual void place_particles(World& world, double dt) = 0;
  // Step 4: applies the summed reactions and advances the bodies by dt.
  virtual void advance(World& world, double dt) = 0;
  // The largest step the bodies allow (fast bodies must not cross a particle per step).
  virtual double max_time_step(const World&) const { return std::numeric_limits<double>::max(); }

  // The bodies' surfaces in their current pose, one piece per body, for a viewer stepping the
  // world live; empty for a system without meshes.
  virtual std::vector<MeshPiece> surface_meshes() const { return {}; }

  // Outputs, called by the run: `open` once before the first frame; `write_frame` per frame
  // returns the files it wrote (relative to out_dir) so they join the frame's .pvd entry.
  virtual void open_outputs(const std::filesystem::path& out_dir, bool write_frames) = 0;
  virtual std::vector<std::string> write_frame(const std::filesystem::path& out_dir, int frame,
                                               double time) = 0;

  // Checkpoints (World::save_state): the bodies' state and where their outputs stand. A restore
  // happens after prepare() and open_outputs(), in a fresh world or in the one that saved (a run
  // continues from exactly what it saved, as a resumed run does).
  virtual void save_state(StateWriter&) const {}
  virtual void restore_state(StateReader&) {}
};

}  // namespace upf
