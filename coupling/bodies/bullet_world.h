// The Bullet dynamics world that moves the rigid bodies (E. Coumans, Bullet Physics SDK,
// btDiscreteDynamicsWorld with the sequential impulse constraint solver). Bullet is built in
// double precision here (Debian's *-float64 libraries) and stepped on one thread, so its
// results do not depend on upf's thread count.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace upf {

class BulletWorld {
 public:
  explicit BulletWorld(const Eigen::Vector3d& gravity);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  // Adds a body; the world does not own it (the caller keeps it alive until the world dies).
  void add(btRigidBody* body);
  // A static box (a container wall slab): centre and half extents in metres. Owned here.
  void add_static_box(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents,
                      double friction, double restitution, double margin);
  // One step of exactly dt (no sub-stepping, no interpolation).
  void step(double dt);

 private:
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<btRigidBody*> bodies_;
  std::vector<std::unique_ptr<btCollisionShape>> owned_shapes_;
  std::vector<std::unique_ptr<btRigidBody>> owned_bodies_;
};

inline btVector3 to_bt(const Eigen::Vector3d& v) {
  return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}
inline Eigen::Vector3d from_bt(const btVector3& v) {
  return {double(v.x()), double(v.y()), double(v.z())};
}

}  // namespace upf
