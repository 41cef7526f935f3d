#include "coupling/bodies/rigid_body_system.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "coupling/mesh/closed_mesh.h"
#include "framework/boundary/slip_normal_fields.h"
#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/core/vec3_eigen.h"
#include "framework/world/world.h"

namespace upf {

namespace {

// Bullet's collision margin: a tenth of the spacing keeps contacts within a particle's reach of
// the surface (Bullet's default, 4 cm, is two particles at the usual 2 cm spacing).
constexpr double kMarginPerSpacing = 0.1;
// The outer sample layer lies half a spacing under the mesh surface (bodies_section.cpp); the
// penetration guard puts a particle that got inside back a quarter spacing off the surface,
// closer than fluid rests (about half a spacing), so the boundary forces take over from there.
constexpr double kLayerDepthPerSpacing = 0.5;
constexpr double kGuardClearancePerSpacing = 0.25;

btTransform to_bt(const Eigen::Vector3d& origin, const Eigen::Quaterniond& q) {
  btTransform t;
  t.setOrigin(upf::to_bt(origin));
  t.setRotation(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())));
  return t;
}

}  // namespace

RigidBodySystem::RigidBodySystem(std::vector<Body> bodies, std::vector<StaticWall> walls,
                                 double spacing, const Eigen::Vector3d& gravity)
    : bodies_(std::move(bodies)),
      walls_(std::move(walls)),
      spacing_(spacing),
      gravity_(gravity),
      guard_(kLayerDepthPerSpacing * spacing, kGuardClearancePerSpacing * spacing) {
  const double margin = kMarginPerSpacing * spacing_;
  for (Body& b : bodies_) {
    const BodySource& s = b.source;
    if (s.kind == BodyKind::Dynamic) {
      // Principal axes: a right-handed eigenbasis of the inertia tensor.
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s.mass->inertia);
      Eigen::Matrix3d axes = eig.eigenvectors();
      if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
      b.origin0 = s.mass->center_of_mass;
      b.rotation0 = Eigen::Quaterniond(axes).normalized();
    } else {
      b.origin0 = s.pivot;
      b.rotation0 = Eigen::Quaterniond::Identity();
    }
    const Eigen::Matrix3d to_local = b.rotation0.toRotationMatrix().transpose();
    b.local_vertices.clear();
    for (const auto& v : s.mesh.vertices) {
      b.local_vertices.push_back(to_local * (v - b.origin0));
      b.reach = std::max(b.reach, b.local_vertices.back().norm());
    }
    if (is_closed(s.mesh)) {
      TriangleMesh local{b.local_vertices, s.mesh.triangles, s.mesh.source};
      b.inside = std::make_unique<MeshInsideTest>(std::move(local), spacing_);
    }
    guarded_meshes_.push_back(b.inside ? &b.inside->data() : nullptr);
    b.shape =
        make_body_shape(s.mesh, b.local_vertices, s.kind, s.mass ? s.mass->volume : 0.0, margin);
  }
  build_bullet();
  read_states();
}

void RigidBodySystem::build_bullet() {
  bullet_.reset();  // removes the bodies from the old world before they are replaced
  bullet_ = std::make_unique<BulletWorld>(gravity_);
  const double margin = kMarginPerSpacing * spacing_;
  for (const auto& w : walls_)
    bullet_->add_static_box(w.center, w.half_extents, w.friction, w.restitution, margin);
  for (Body& b : bodies_) {
    const BodySource& s = b.source;
    const double mass = s.kind == BodyKind::Dynamic ? s.mass->mass : 0.0;
    btVector3 inertia(0, 0, 0);
    if (s.kind == BodyKind::Dynamic) {
      // The diagonal of the inertia tensor in the principal frame.
      const Eigen::Matrix3d to_local = b.rotation0.toRotationMatrix().transpose();
      const Eigen::Matrix3d local = to_local * s.mass->inertia * to_local.transpose();
      inertia = btVector3(btScalar(local(0, 0)), btScalar(local(1, 1)), btScalar(local(2, 2)));
    }
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, b.shape.shape.get(),
                                                  inertia);
    info.m_startWorldTransform = to_bt(b.origin0, b.rotation0);
    info.m_friction = btScalar(s.friction);
    info.m_restitution = btScalar(s.restitution);
    b.rigid = std::make_unique<btRigidBody>(info);
    if (s.kind == BodyKind::Dynamic) {
      b.rigid->setLinearVelocity(upf::to_bt(s.velocity));
      b.rigid->setAngularVelocity(upf::to_bt(s.angular_velocity));
    } else if (s.kind == BodyKind::Kinematic) {
      b.rigid->setCollisionFlags(b.rigid->getCollisionFlags() |
                                 btCollisionObject::CF_KINEMATIC_OBJECT);
    }
    // Bodies in a fluid never sleep: the fluid keeps pushing them.
    b.rigid->setActivationState(DISABLE_DEACTIVATION);
    bullet_->add(b.rigid.get());
  }
}

RigidBodySystem::~RigidBodySystem() {
  bullet_.reset();  // removes the bodies before they are destroyed
}

void RigidBodySystem::add_particles(Particles& particles) const {
  std::vector<Vec3>& local = particles.vector_field(kBodyLocalPositionField);
  std::vector<Vec3>& normal = particles.vector_field(kBodyLocalNormalField);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    const ParticleType type =
        body.source.kind == BodyKind::Dynamic ? ParticleType::Rigid : ParticleType::Frozen;
    const Eigen::Matrix3d to_local = body.rotation0.toRotationMatrix().transpose();
    for (std::size_t k = 0; k < body.source.samples.size(); ++k) {
      const Eigen::Vector3d& x = body.source.samples[k];
      // add() appends a zero to every named field; the body-frame values go in that slot.
      const std::size_t i = particles.add(to_vec3(x), to_vec3(body.source.velocity), Real(0), type,
                                          body.source.material_id, BodyId(b));
      local[i] = to_vec3(to_local * (x - body.origin0));
      normal[i] = to_vec3(to_local * body.source.normals[k]);
    }
  }
}

void RigidBodySystem::prepare(World& world) {
  // Akinci volumes, over each particle's own body, are World::prepare's.
  guard_.request(world);
}

namespace {

Vec3d plain(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

BodyPose pose_of(const Eigen::Vector3d& origin, const Eigen::Matrix3d& rotation,
                 const Eigen::Vector3d& velocity, const Eigen::Vector3d& angular_velocity) {
  BodyPose f;
  f.origin = plain(origin);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) f.rotation.m[3 * r + c] = rotation(r, c);
  f.velocity = plain(velocity);
  f.angular_velocity = plain(angular_velocity);
  return f;
}

}  // namespace

BodyPose RigidBodySystem::frame_of(const Body& body, double t) const {
  BodyPose f;
  if (body.source.kind == BodyKind::Dynamic) {
    const btTransform& tr = body.rigid->getCenterOfMassTransform();
    const btQuaternion q = tr.getRotation();
    f = pose_of(from_bt(tr.getOrigin()),
                Eigen::Quaterniond(double(q.w()), double(q.x()), double(q.y()), double(q.z()))
                    .normalized()
                    .toRotationMatrix(),
                from_bt(body.rigid->getLinearVelocity()),
                from_bt(body.rigid->getAngularVelocity()));
  } else if (body.motion) {
    const RigidPose pose = body.motion->pose(t);
    const RigidVelocity v = body.motion->velocity(t);
    f = pose_of(body.origin0 + pose.position, pose.orientation.toRotationMatrix(), v.linear,
                v.angular);
  } else {
    f.origin = plain(body.origin0);
  }
  f.moves = body.source.kind == BodyKind::Dynamic || (body.motion && body.motion->moves());
  return f;
}

void RigidBodySystem::update_kinematic(double t, double dt) {
  for (Body& b : bodies_) {
    if (!b.motion) continue;
    // Bullet derives a kinematic body's velocity from its last pose (the interpolation
    // transform) and the pose it will have at the step's end, which is set here.
    const RigidPose end = b.motion->pose(t + dt);
    const Eigen::Quaterniond q = (end.orientation * b.rotation0).normalized();
    b.rigid->setWorldTransform(to_bt(b.origin0 + end.position, q));
  }
}

void RigidBodySystem::place_particles(World& world, double dt) {
  const double t = world.time();
  std::vector<BodyPose> poses(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) poses[b] = frame_of(bodies_[b], t);
  update_kinematic(t, dt);

  if (DevicePipeline* device = world.device()) {
    device->place_body_particles(poses, kBodyLocalPositionField);
    return;
  }
  Particles& p = world.particles();
  // With free-slip boundaries, their normals turn with the bodies (slip_normal.h).
  std::vector<Vec3>* local_slip = p.find_vector(kBodySlipNormalField);
  std::vector<Vec3>* slip = p.find_vector(kSlipNormalField);
  const bool turn = local_slip != nullptr && slip != nullptr;
  world.executor().run(
      all_particles(p.size()),
      PlaceBodyParticlesStage{poses.data(), p.body.data(),
                              p.find_vector(kBodyLocalPositionField)->data(), p.position.data(),
                              p.velocity.data(), turn ? local_slip->data() : nullptr,
                              turn ? slip->data() : nullptr});
}

void RigidBodySystem::advance(World& world, double dt) {
  // Fixed-point sums: the same bits whatever order the particles are in (they are reordered for
  // locality), so a body scene is identical for any thread count and any reordering.
  std::vector<Vec3d> origins(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    origins[b] = plain(from_bt(bodies_[b].rigid->getCenterOfMassPosition()));
  std::vector<BodyWrench> sums(bodies_.size());
  if (DevicePipeline* device = world.device()) {
    device->body_wrenches(origins, sums);
  } else if (const std::vector<Vec3>& reaction = world.coupling()[CouplingArray::BoundaryForce];
             !reaction.empty()) {
    const Particles& p = world.particles();
    const RigidReactionWrench wrench{p.position.data(), reaction.data(), p.body.data(),
                                     origins.data()};
    for (std::size_t i = 0; i < p.owned_size(); ++i) {
      const BodyId b = p.body[i];
      if (b == kNoBody) continue;  // a static or kinematic body's frozen particles count too
      sums[std::size_t(b)] = BodyWrenchPlus{}(sums[std::size_t(b)], wrench(std::uint32_t(i)));
    }
  }
  // Across ranks each rank summed its own particles; integer sums over ranks are the one-rank sums
  // exactly, so every rank steps the same Bullet world with the same forces.
  if (const ParticleDomain* domain = world.domain()) {
    std::vector<std::int64_t> units;
    for (const BodyWrench& s : sums) {
      units.insert(units.end(), std::begin(s.units), std::end(s.units));
      units.push_back(s.broken);
    }
    domain->sum(units.data(), units.size());
    for (std::size_t b = 0; b < sums.size(); ++b) {
      std::copy_n(units.begin() + std::ptrdiff_t(7 * b), 6, sums[b].units);
      sums[b].broken = units[7 * b + 6] != 0;
    }
  }
  std::vector<Eigen::Vector3d> force(bodies_.size()), torque(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    force[b] = {sums[b].value(0), sums[b].value(1), sums[b].value(2)};
    torque[b] = {sums[b].value(3), sums[b].value(4), sums[b].value(5)};
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    Body& body = bodies_[b];
    body.state.fluid_force = force[b];
    body.state.fluid_torque = torque[b];
    if (body.source.kind != BodyKind::Dynamic) continue;
    body.rigid->applyCentralForce(upf::to_bt(force[b]));
    body.rigid->applyTorque(upf::to_bt(torque[b]));
  }
  bullet_->step(dt);
  time_ = world.time() + dt;
  const std::vector<Eigen::Vector3d> stopped = guard_surfaces(world, time_, dt);
  for (std::size_t b = 0; b < bodies_.size(); ++b) bodies_[b].state.fluid_force += stopped[b];
  read_states();
}

std::vector<Eigen::Vector3d> RigidBodySystem::guard_surfaces(World& world, double t, double dt) {
  std::vector<BodyPose> poses(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) poses[b] = frame_of(bodies_[b], t);
  std::vector<Eigen::Vector3d> mean_force(bodies_.size(), Eigen::Vector3d::Zero());
  // The impulses change the bodies' velocities now, after Bullet's step: the stopped fluid's
  // momentum goes to the body in the same step, in the order of the particles' stable ids.
  for (const SurfaceHit& s : guard_.apply(world, poses, guarded_meshes_)) {
    Body& body = bodies_[s.body];
    const Eigen::Vector3d impulse(s.impulse.x, s.impulse.y, s.impulse.z);
    const Eigen::Vector3d point(s.point.x, s.point.y, s.point.z);
    mean_force[s.body] += impulse / dt;
    if (body.source.kind != BodyKind::Dynamic) continue;
    body.rigid->applyImpulse(upf::to_bt(impulse),
                             upf::to_bt(point - from_bt(body.rigid->getCenterOfMassPosition())));
  }
  return mean_force;
}

void RigidBodySystem::read_states() {
  for (Body& b : bodies_) {
    const btTransform& tr = b.rigid->getCenterOfMassTransform();
    const btQuaternion q = tr.getRotation();
    const Eigen::Quaterniond now(double(q.w()), double(q.x()), double(q.y()), double(q.z()));
    b.state.position = from_bt(tr.getOrigin());
    b.state.orientation = (now * b.rotation0.conjugate()).normalized();
    b.state.velocity = from_bt(b.rigid->getLinearVelocity());
    b.state.angular_velocity = from_bt(b.rigid->getAngularVelocity());
  }
}

double RigidBodySystem::max_time_step(const World& world) const {
  // A body's fastest point moves at most 0.4 particle spacings per step, like the fluid's CFL.
  double fastest = 0;
  for (const Body& b : bodies_) {
    if (b.source.kind == BodyKind::Static) continue;
    fastest =
        std::max(fastest, b.state.velocity.norm() + b.state.angular_velocity.norm() * b.reach);
  }
  if (fastest <= 0) return BodySystem::max_time_step(world);
  return world.settings().time.cfl * double(world.settings().spacing) / fastest;
}

Eigen::Vector3d RigidBodySystem::momentum() const {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const Body& b : bodies_)
    if (b.source.kind == BodyKind::Dynamic) total += b.source.mass->mass * b.state.velocity;
  return total;
}

std::vector<NamedBodyState> RigidBodySystem::body_states() const {
  std::vector<NamedBodyState> states;
  for (const Body& b : bodies_) states.push_back({b.source.name, b.state});
  return states;
}

bool RigidBodySystem::set_velocity(std::size_t index, const Eigen::Vector3d& velocity,
                                   const Eigen::Vector3d& angular_velocity) {
  if (index >= bodies_.size() || bodies_[index].source.kind != BodyKind::Dynamic) return false;
  Body& b = bodies_[index];
  b.rigid->setLinearVelocity(to_bt(velocity));
  b.rigid->setAngularVelocity(to_bt(angular_velocity));
  b.rigid->setInterpolationLinearVelocity(b.rigid->getLinearVelocity());
  b.rigid->setInterpolationAngularVelocity(b.rigid->getAngularVelocity());
  read_states();
  return true;
}

std::vector<MeshPiece> RigidBodySystem::surface_meshes() const {
  // Each body's mesh in its current pose: x = X + R r0 over the body-frame vertices.
  std::vector<MeshPiece> pieces;
  for (const Body& b : bodies_) {
    const btTransform& tr = b.rigid->getCenterOfMassTransform();
    MeshPiece piece;
    piece.name = b.source.name;
    for (const auto& r : b.local_vertices) piece.vertices.push_back(from_bt(tr * upf::to_bt(r)));
    piece.triangles = b.source.mesh.triangles;
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

namespace {

void put_vector3(StateWriter& out, const Eigen::Vector3d& v) {
  for (int a = 0; a < 3; ++a) out.put(v[a]);
}
Eigen::Vector3d get_vector3(StateReader& in) {
  Eigen::Vector3d v;
  for (int a = 0; a < 3; ++a) v[a] = in.get<double>();
  return v;
}
void put_bt(StateWriter& out, const btVector3& v) {
  for (int a = 0; a < 3; ++a) out.put(v[a]);
}
btVector3 get_bt(StateReader& in) {
  btVector3 v;
  for (int a = 0; a < 3; ++a) v[a] = in.get<btScalar>();
  return v;
}

}  // namespace

void RigidBodySystem::save_state(StateWriter& out) const {
  out.put(time_);
  out.put(std::uint64_t(bodies_.size()));
  for (const Body& b : bodies_) {
    const btTransform& tr = b.rigid->getWorldTransform();
    for (int r = 0; r < 3; ++r) put_bt(out, tr.getBasis()[r]);
    put_bt(out, tr.getOrigin());
    put_bt(out, b.rigid->getLinearVelocity());
    put_bt(out, b.rigid->getAngularVelocity());
    put_vector3(out, b.state.fluid_force);
    put_vector3(out, b.state.fluid_torque);
  }
}

void RigidBodySystem::restore_state(StateReader& in) {
  time_ = in.get<double>();
  in.expect(in.get<std::uint64_t>() == bodies_.size(), "the number of bodies");
  // A fresh Bullet world, as a resumed run makes: Bullet's contact caches (persistent manifolds,
  // the pair cache's order) are not part of the state, so the run that saved starts over from
  // exactly the same place.
  build_bullet();
  for (Body& b : bodies_) {
    btTransform tr;
    btMatrix3x3 basis;
    for (int r = 0; r < 3; ++r) basis[r] = get_bt(in);
    tr.setBasis(basis);
    tr.setOrigin(get_bt(in));
    b.rigid->setWorldTransform(tr);
    b.rigid->setInterpolationWorldTransform(tr);
    b.rigid->setLinearVelocity(get_bt(in));
    b.rigid->setAngularVelocity(get_bt(in));
    b.rigid->setInterpolationLinearVelocity(b.rigid->getLinearVelocity());
    b.rigid->setInterpolationAngularVelocity(b.rigid->getAngularVelocity());
    b.state.fluid_force = get_vector3(in);
    b.state.fluid_torque = get_vector3(in);
  }
  read_states();
}

}  // namespace upf
