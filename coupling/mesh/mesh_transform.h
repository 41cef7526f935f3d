// Where a mesh goes in the world, applied once at load time. Convention, in this order:
//
//   x_world = position + R * (scale .* (unit * x_file))
//
// 1. unit:     length of one file unit in metres ("mm" -> 0.001); CAD files are often in mm.
// 2. scale:    per axis, in the mesh's own frame, about the file's origin (negative mirrors).
// 3. rotation: a unit quaternion, about the file's origin; scene files give it as an axis and an
//              angle in degrees (right-hand rule), see rotation_from_axis_angle_degrees().
// 4. position: translation in metres: the file's origin lands here.
//
// The file's origin is the pivot: a mesh modelled around its centre rotates about its centre.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>

namespace upf {

struct MeshTransform {
  double unit = 1.0;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& file_point) const;
  // An odd number of negative scale factors turns the surface inside out; the loader then
  // reverses the windings so that normals keep pointing the same way relative to the surface.
  bool mirrors() const { return scale.x() * scale.y() * scale.z() < 0; }
};

// Rotation by `degrees` about `axis` (any non-zero length), right-hand rule.
Eigen::Quaterniond rotation_from_axis_angle_degrees(const Eigen::Vector3d& axis, double degrees);

// Metres per unit for "m", "cm", "mm", "um", "km", "in", "ft"; nothing for other names.
std::optional<double> length_unit_in_metres(std::string_view name);
// The names length_unit_in_metres() knows, for error messages: "m, cm, mm, um, km, in, ft".
std::string length_unit_names();

// Throws InputError at `where` (a JSON path or the file) when the transform cannot be applied:
// unit not finite and positive, a zero or non-finite scale factor, a non-unit rotation, a
// non-finite position.
void require_valid_transform(const MeshTransform& transform, const std::string& where);

}  // namespace upf
