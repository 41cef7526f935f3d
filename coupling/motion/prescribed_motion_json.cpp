#include "coupling/motion/prescribed_motion_json.h"

#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

#include "coupling/mesh/mesh_source_json.h"

namespace upf {

namespace {

constexpr double kMaxTime = 1e7;  // s, the scene's longest end time

std::string seconds(double t) {
  std::ostringstream out;
  out << t << " s";
  return out.str();
}

// check_keys(), and whether every key was known: a misspelt key fails the read, so that a typo
// never silently leaves a body at rest.
bool known_keys(JsonInput& input, const nlohmann::json& object, const std::string& path,
                const std::vector<std::string>& allowed) {
  input.check_keys(object, path, allowed);
  for (auto it = object.begin(); it != object.end(); ++it)
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) return false;
  return true;
}

// "keyframes": every key is read and checked, so that all problems are listed at once.
std::optional<PrescribedMotion> read_keyframes(const nlohmann::json& node, const std::string& path,
                                               JsonInput& input) {
  const std::string where = JsonInput::child(path, "keyframes");
  const nlohmann::json& array = node.at("keyframes");
  if (!array.is_array()) {
    input.problem(where, "expected an array of keyframes, found " + json_type_name(array));
    return std::nullopt;
  }
  if (array.empty()) {
    input.problem(where, "at least one keyframe is required");
    return std::nullopt;
  }
  std::vector<std::pair<double, RigidPose>> keys;
  bool ok = true;
  // The last readable time and its index: a bad time is not compared with the next one.
  std::optional<std::pair<std::size_t, double>> previous;
  double latest = 0;  // the largest readable time, which a loop period must cover
  for (std::size_t i = 0; i < array.size(); ++i) {
    const std::string key_path = JsonInput::child(where, i);
    const nlohmann::json& key = array[i];
    if (!input.expect_object(key, key_path)) {
      ok = false;
      continue;
    }
    if (!known_keys(input, key, key_path, {"time", "position", "rotation"})) ok = false;
    const auto time = input.required_number(key, key_path, "time", 0, kMaxTime, false, "s");
    if (time && previous && !(*time > previous->second)) {
      input.problem(JsonInput::child(key_path, "time"),
                    "keyframe times must increase strictly: keyframe " + std::to_string(i) +
                        " at " + seconds(*time) + " follows keyframe " +
                        std::to_string(previous->first) + " at " + seconds(previous->second));
      ok = false;
    }
    if (time) {
      previous = {i, *time};
      latest = std::max(latest, *time);
    }
    const auto position = input.vec3(key, key_path, "position", false);
    const auto rotation = read_rotation(key, key_path, input);
    if (!time || !rotation || (key.contains("position") && !position)) {
      ok = false;
      continue;
    }
    keys.push_back({*time, {position.value_or(Eigen::Vector3d::Zero()), *rotation}});
  }

  double loop = 0;
  if (node.contains("loop")) {
    const auto period = input.required_number(node, path, "loop", 0, kMaxTime, true, "s");
    if (!period) return std::nullopt;
    if (*period < latest) {
      input.problem(JsonInput::child(path, "loop"),
                    "the loop period " + seconds(*period) + " is shorter than the last " +
                        "keyframe's time " + seconds(latest) + " (it must be at least that)");
      return std::nullopt;
    }
    loop = *period;
  }
  if (!ok) return std::nullopt;
  return PrescribedMotion::keyframes(std::move(keys), loop);
}

}  // namespace

std::optional<PrescribedMotion> read_prescribed_motion(const nlohmann::json& node,
                                                       const std::string& path, JsonInput& input) {
  if (!input.expect_object(node, path)) return std::nullopt;
  const bool known = known_keys(
      input, node, path, {"linear_velocity", "angular_velocity", "keyframes", "loop", "pivot"});
  const bool velocities = node.contains("linear_velocity") || node.contains("angular_velocity");
  if (node.contains("keyframes")) {
    if (velocities) {
      input.problem(path,
                    "give either velocities (linear_velocity, angular_velocity) or keyframes, "
                    "not both");
      return std::nullopt;
    }
    auto motion = read_keyframes(node, path, input);
    return known ? motion : std::nullopt;
  }
  if (node.contains("loop")) {
    input.problem(JsonInput::child(path, "loop"), "a loop period needs keyframes to repeat");
    return std::nullopt;
  }
  const auto linear = input.vec3(node, path, "linear_velocity", false);
  const auto angular = input.vec3(node, path, "angular_velocity", false);
  if (!known || (node.contains("linear_velocity") && !linear) ||
      (node.contains("angular_velocity") && !angular))
    return std::nullopt;
  return PrescribedMotion::constant(linear.value_or(Eigen::Vector3d::Zero()),
                                    angular.value_or(Eigen::Vector3d::Zero()));
}

std::optional<Eigen::Vector3d> read_pivot(const nlohmann::json& node, const std::string& path,
                                          JsonInput& input) {
  if (!node.is_object()) return std::nullopt;  // read_prescribed_motion() reports that
  return input.vec3(node, path, "pivot", false);
}

}  // namespace upf
