// A body of a scene file, read and checked: its mesh placed in the world, its surface samples
// (the boundary particles), and for a dynamic body its mass properties. Reading does all the
// work that can fail on bad input, so `upf validate` reports broken meshes before any run.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "coupling/mesh/mass_properties.h"
#include "coupling/mesh/triangle_mesh.h"
#include "framework/particles/particles.h"

namespace upf {

enum class BodyKind {
  Dynamic,    // a rigid material: Bullet moves it under gravity, contacts and fluid forces
  Static,     // a frozen material without motion: an obstacle or container from a mesh
  Kinematic,  // a frozen material with a prescribed motion: a paddle, a mixer
};

struct BodySource {
  std::string name;
  std::string material;
  MaterialId material_id = 0;  // index in SceneDescription::materials
  BodyKind kind = BodyKind::Static;
  TriangleMesh mesh;                     // in world coordinates, oriented outward
  std::vector<Eigen::Vector3d> samples;  // boundary particles, world coordinates
  // Outward unit normal of each sample on the surface; zero for the inner layer.
  std::vector<Eigen::Vector3d> normals;
  std::optional<MassProperties> mass;                          // dynamic bodies only
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // m/s, initial
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, initial, world axes
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  // static/kinematic: origin of the body frame
  double friction = 0.5, restitution = 0.1;
};

}  // namespace upf
