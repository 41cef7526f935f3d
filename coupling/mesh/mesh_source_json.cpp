#include "coupling/mesh/mesh_source_json.h"

#include <cmath>

namespace upf {

namespace {

// "scale": one number for all axes, or one per axis; absent: 1.
std::optional<Eigen::Vector3d> read_scale(JsonInput& input, const nlohmann::json& node,
                                          const std::string& path) {
  auto it = node.find("scale");
  if (it == node.end()) return Eigen::Vector3d::Ones();
  if (it->is_number()) return Eigen::Vector3d::Constant(it->get<double>());
  return input.vec3(node, path, "scale", true);
}

}  // namespace

std::optional<Eigen::Quaterniond> read_rotation(const nlohmann::json& node, const std::string& path,
                                                JsonInput& input) {
  auto it = node.find("rotation");
  if (it == node.end()) return Eigen::Quaterniond::Identity();
  const std::string where = JsonInput::child(path, "rotation");
  if (!input.expect_object(*it, where)) return std::nullopt;
  input.check_keys(*it, where, {"axis", "degrees"});
  const auto axis = input.vec3(*it, where, "axis", true);
  const auto degrees = input.required_number(*it, where, "degrees", -1e6, 1e6, false, "degrees");
  if (!axis || !degrees) return std::nullopt;
  if (axis->norm() == 0) {
    input.problem(JsonInput::child(where, "axis"), "the rotation axis must not be zero");
    return std::nullopt;
  }
  return rotation_from_axis_angle_degrees(*axis, *degrees);
}

std::optional<MeshSource> read_mesh_source(const nlohmann::json& node, const std::string& path,
                                           const std::filesystem::path& base_directory,
                                           JsonInput& input) {
  if (!input.expect_object(node, path)) return std::nullopt;
  input.check_keys(node, path, {"file", "units", "scale", "rotation", "position"});
  MeshSource out;
  bool ok = true;
  if (const auto file = input.string(node, path, "file", true)) {
    out.file = base_directory / *file;  // an absolute file replaces the base
  } else {
    ok = false;
  }
  if (const auto units = input.string(node, path, "units", false)) {
    if (const auto metres = length_unit_in_metres(*units)) {
      out.transform.unit = *metres;
    } else {
      input.problem(JsonInput::child(path, "units"),
                    "unknown length unit '" + *units + "' (use " + length_unit_names() + ")");
      ok = false;
    }
  } else if (node.contains("units")) {
    ok = false;
  }
  const auto scale = read_scale(input, node, path);
  if (scale && (!scale->allFinite() || (scale->array() == 0).any())) {
    input.problem(JsonInput::child(path, "scale"), "scale factors must be finite and non-zero");
    ok = false;
  }
  const auto rotation = read_rotation(node, path, input);
  const auto position = input.vec3(node, path, "position", false);
  if (!ok || !scale || !rotation || (node.contains("position") && !position)) return std::nullopt;
  out.transform.scale = *scale;
  out.transform.rotation = *rotation;
  out.transform.position = position.value_or(Eigen::Vector3d::Zero());
  return out;
}

}  // namespace upf
