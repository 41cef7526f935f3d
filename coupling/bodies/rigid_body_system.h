// Rigid bodies and mesh obstacles in the particle world (DESIGN.md, "One step", stages 1 and 4):
// Bullet moves the bodies; their boundary particles, sampled on the mesh surface, follow them;
// fluids push the particles and the pushes, summed per body, push the bodies (two-way coupling of
// Akinci et al. 2012, "Versatile rigid-fluid coupling for incompressible SPH", ACM TOG 31(4)).
//
// Body frames: a dynamic body's frame sits at its centre of mass along its principal axes, so
// Bullet gets a diagonal inertia tensor; a static or kinematic body's frame sits at its pivot
// with the world's axes. Each boundary particle keeps its position in the body frame (field
// kBodyLocalPositionField) and is placed at x = X + R r0 with v = V + w x (x - X) every step.
//
// Boundary volumes (Akinci's V_b = 1 / sum_k W_bk) sum over the particle's own body only
// (compute_boundary_volumes, called once by World::prepare): a body's sampling does not change
// as it moves past walls and other bodies.
//
// Per-body sums of forces and torques are fixed-point (BodyWrench), the penetration guard's
// impulses reach the bodies in particle-id order, and Bullet steps on one thread: the same bits
// for any thread count and whatever order the particles are in memory. The per-particle work
// (placement, sums, guard) is body_particle_stages.h, run by the world's executor or, when the
// world steps on a device, by the device pipeline: the bodies stay here, the particles there.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coupling/bodies/body_source.h"
#include "coupling/bodies/bullet_world.h"
#include "coupling/bodies/collision_shapes.h"
#include "coupling/bodies/penetration_guard.h"
#include "coupling/mesh/mesh_inside_test.h"
#include "coupling/motion/prescribed_motion.h"
#include "framework/scene/scene.h"
#include "framework/world/body_system.h"

namespace upf {

// A wall slab of a particle container, for Bullet contacts with the container.
struct StaticWall {
  Eigen::Vector3d center, half_extents;
  double friction = 0.5, restitution = 0.1;
};

class RigidBodySystem : public BodySystem {
 public:
  struct Body {
    BodySource source;
    std::optional<PrescribedMotion> motion;                         // kinematic bodies
    Eigen::Vector3d origin0 = Eigen::Vector3d::Zero();              // initial frame origin
    Eigen::Quaterniond rotation0 = Eigen::Quaterniond::Identity();  // initial frame axes
    std::vector<Eigen::Vector3d> local_vertices;                    // mesh in the body frame
    std::unique_ptr<MeshInsideTest> inside;  // closed meshes, in the body frame: guarded
    double reach = 0;                        // largest distance of a vertex from the frame origin
    OwnedShape shape;
    std::unique_ptr<btRigidBody> rigid;
    BodyState state;
  };

  // `spacing` is the particle spacing (Bullet's collision margin is a fraction of it).
  RigidBodySystem(std::vector<Body> bodies, std::vector<StaticWall> walls, double spacing,
                  const Eigen::Vector3d& gravity);
  ~RigidBodySystem() override;

  // Adds each body's boundary particles (type from its material, body id = its index).
  void add_particles(Particles& particles) const;

  std::string_view name() const override { return "bodies"; }
  void prepare(World& world) override;
  void place_particles(World& world, double dt) override;
  void advance(World& world, double dt) override;
  double max_time_step(const World& world) const override;
  std::vector<MeshPiece> surface_meshes() const override;
  std::vector<NamedBodyState> body_states() const override;
  // Dynamic bodies only: a static or kinematic body's motion is prescribed.
  bool set_velocity(std::size_t index, const Eigen::Vector3d& velocity,
                    const Eigen::Vector3d& angular_velocity) override;
  void save_state(StateWriter& out) const override;
  void restore_state(StateReader& in) override;

  const std::vector<Body>& bodies() const { return bodies_; }
  // The state of body `b` now (its fluid force and torque: those of the last step).
  const BodyState& state(std::size_t b) const { return bodies_[b].state; }
  // Momentum of the dynamic bodies, kg m/s.
  Eigen::Vector3d momentum() const;
  // Fluid particles the penetration guard moved in the last step.
  std::size_t guarded_particles() const { return guard_.corrected(); }

 private:
  // A new Bullet world with the walls and every body at its start (constructor, restore_state).
  void build_bullet();
  void read_states();
  void update_kinematic(double t, double dt);
  // Where body b stands at time t (a dynamic body: where Bullet has it now).
  BodyPose frame_of(const Body& body, double t) const;
  // Stops fluid particles at the bodies' surfaces; returns the impulses' mean force per body.
  std::vector<Eigen::Vector3d> guard_surfaces(World& world, double t, double dt);

  std::vector<Body> bodies_;
  std::vector<StaticWall> walls_;
  double spacing_;
  Eigen::Vector3d gravity_;
  std::unique_ptr<BulletWorld> bullet_;
  PenetrationGuard guard_;
  std::vector<const MeshParityData*> guarded_meshes_;  // per body; null: not guarded
  double time_ = 0;
};

}  // namespace upf
