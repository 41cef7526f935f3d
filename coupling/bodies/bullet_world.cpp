#include "coupling/bodies/bullet_world.h"

#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>

namespace upf {

BulletWorld::BulletWorld(const Eigen::Vector3d& gravity)
    : config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                       solver_.get(), config_.get())) {
  // Moving concave meshes collide only once GImpact's algorithm is registered.
  btGImpactCollisionAlgorithm::registerAlgorithm(dispatcher_.get());
  world_->setGravity(to_bt(gravity));
}

BulletWorld::~BulletWorld() {
  for (btRigidBody* b : bodies_) world_->removeRigidBody(b);
}

void BulletWorld::add(btRigidBody* body) {
  world_->addRigidBody(body);
  bodies_.push_back(body);
}

void BulletWorld::add_static_box(const Eigen::Vector3d& center, const Eigen::Vector3d& half,
                                 double friction, double restitution, double margin) {
  auto shape = std::make_unique<btBoxShape>(to_bt(half));
  shape->setMargin(btScalar(margin));
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(center));
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape.get());
  info.m_startWorldTransform = pose;
  info.m_friction = btScalar(friction);
  info.m_restitution = btScalar(restitution);
  auto body = std::make_unique<btRigidBody>(info);
  add(body.get());
  owned_shapes_.push_back(std::move(shape));
  owned_bodies_.push_back(std::move(body));
}

void BulletWorld::step(double dt) {
  // maxSubSteps = 0: one internal step of exactly dt.
  world_->stepSimulation(btScalar(dt), 0);
}

}  // namespace upf
