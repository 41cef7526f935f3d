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

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/mesh_piece.h"
#include "framework/core/real.h"

namespace upf {

class World;
class StateWriter;
class StateReader;

// The state of one body, as a run reports it (bodies.csv) and tests read it.
struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // frame origin (centre of mass if dynamic)
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // relative to the start
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d fluid_force = Eigen::Vector3d::Zero();   // N, the last step's
  Eigen::Vector3d fluid_torque = Eigen::Vector3d::Zero();  // N m, about the frame origin
};

struct NamedBodyState {
  std::string name;
  BodyState state;
};

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

  // What the run writes and viewers draw (framework/run/body_outputs.h); the system itself
  // writes nothing. Every body's state now, in a fixed order: the rows of bodies.csv.
  virtual std::vector<NamedBodyState> body_states() const = 0;
  // Sets body `index`'s (body_states() order) velocity and angular velocity (world axes, about
  // its frame origin) from now on: for scripts and the Python module. False for a body whose
  // motion is not the system's to change (static, or prescribed), or an index out of range.
  virtual bool set_velocity(std::size_t /*index*/, const Eigen::Vector3d& /*velocity*/,
                            const Eigen::Vector3d& /*angular_velocity*/) {
    return false;
  }
  // The bodies' surfaces in their current pose, one piece per body in body_states() order;
  // empty for a system without meshes.
  virtual std::vector<MeshPiece> surface_meshes() const { return {}; }

  // Checkpoints (World::save_state): the bodies' state. A restore happens after prepare(), in a
  // fresh world or in the one that saved (a run continues from exactly what it saved, as a
  // resumed run does).
  virtual void save_state(StateWriter&) const {}
  virtual void restore_state(StateReader&) {}
};

}  // namespace upf
