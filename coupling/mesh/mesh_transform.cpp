#include "coupling/mesh/mesh_transform.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "framework/core/errors.h"

namespace upf {

namespace {
constexpr std::array<std::pair<std::string_view, double>, 7> kLengthUnits = {{
    {"m", 1.0},
    {"cm", 0.01},
    {"mm", 0.001},
    {"um", 1e-6},
    {"km", 1000.0},
    {"in", 0.0254},  // international inch, exact
    {"ft", 0.3048},  // international foot, exact
}};
}  // namespace

Eigen::Vector3d MeshTransform::apply(const Eigen::Vector3d& file_point) const {
  return position + rotation * (scale.cwiseProduct(unit * file_point));
}

Eigen::Quaterniond rotation_from_axis_angle_degrees(const Eigen::Vector3d& axis, double degrees) {
  constexpr double kPi = 3.14159265358979323846;
  return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * kPi / 180.0, axis.normalized()));
}

std::optional<double> length_unit_in_metres(std::string_view name) {
  for (const auto& [unit, metres] : kLengthUnits)
    if (unit == name) return metres;
  return std::nullopt;
}

std::string length_unit_names() {
  std::string names;
  for (const auto& [unit, metres] : kLengthUnits)
    names += (names.empty() ? "" : ", ") + std::string(unit);
  return names;
}

void require_valid_transform(const MeshTransform& transform, const std::string& where) {
  std::vector<InputProblem> problems;
  if (!std::isfinite(transform.unit) || !(transform.unit > 0))
    problems.push_back({where, "the length unit must be a finite positive number of metres"});
  if (!transform.scale.allFinite() || (transform.scale.array() == 0).any())
    problems.push_back({where, "every scale factor must be finite and non-zero"});
  if (!transform.rotation.coeffs().allFinite() ||
      std::abs(transform.rotation.squaredNorm() - 1) > 1e-9)
    problems.push_back({where, "the rotation must be a unit quaternion"});
  if (!transform.position.allFinite()) problems.push_back({where, "the position must be finite"});
  if (!problems.empty()) throw InputError(std::move(problems));
}

}  // namespace upf
