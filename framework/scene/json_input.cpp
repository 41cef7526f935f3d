#include "framework/scene/json_input.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace upf {

namespace {
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}
}  // namespace

std::optional<std::string> did_you_mean(std::string_view word,
                                        const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::string json_type_name(const nlohmann::json& node) {
  if (node.is_number()) return "a number";
  if (node.is_string()) return "a string";
  if (node.is_boolean()) return "a boolean";
  if (node.is_array()) return "an array";
  if (node.is_object()) return "an object";
  return "null";
}

bool JsonInput::expect_object(const nlohmann::json& node, const std::string& path) {
  if (node.is_object()) return true;
  problem(path.empty() ? "/" : path, "expected an object, found " + json_type_name(node));
  return false;
}

void JsonInput::check_keys(const nlohmann::json& object, const std::string& path,
                           const std::vector<std::string>& allowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end()) continue;
    std::string message = "unknown key '" + it.key() + "'";
    if (auto guess = did_you_mean(it.key(), allowed))
      message += " (did you mean '" + *guess + "'?)";
    problem(child(path, it.key()), message);
  }
}

std::optional<double> JsonInput::required_number(const nlohmann::json& object,
                                                 const std::string& path, std::string_view key,
                                                 double lo, double hi, bool lo_open,
                                                 std::string_view unit) {
  const std::string where = child(path, key);
  auto it = object.find(std::string(key));
  if (it == object.end()) {
    problem(where, "missing (a number is required)");
    return std::nullopt;
  }
  if (!it->is_number()) {
    problem(where, "expected a number, found " + json_type_name(*it));
    return std::nullopt;
  }
  const double v = it->get<double>();
  const bool low = lo_open ? !(v > lo) : !(v >= lo);
  if (!std::isfinite(v) || low || v > hi) {
    std::string range =
        std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + "]";
    if (!unit.empty()) range += " " + std::string(unit);
    problem(where, "value " + format_number(v) + " is out of range " + range);
    return std::nullopt;
  }
  return v;
}

double JsonInput::number(const nlohmann::json& object, const std::string& path,
                         std::string_view key, double fallback, double lo, double hi, bool lo_open,
                         std::string_view unit) {
  if (!object.contains(std::string(key))) return fallback;
  return required_number(object, path, key, lo, hi, lo_open, unit).value_or(fallback);
}

double JsonInput::number(const nlohmann::json& object, const std::string& path,
                         const ParamSpec& spec, double fallback) {
  // "1" marks a dimensionless number: a message shows no unit for it.
  const std::string_view unit = spec.unit == "1" ? std::string_view() : spec.unit;
  return number(object, path, spec.name, fallback, spec.min_value, spec.max_value,
                spec.exclusive_min, unit);
}

std::optional<std::string> JsonInput::string(const nlohmann::json& object, const std::string& path,
                                             std::string_view key, bool required) {
  auto it = object.find(std::string(key));
  if (it == object.end()) {
    if (required) problem(child(path, key), "missing (a string is required)");
    return std::nullopt;
  }
  if (!it->is_string()) {
    problem(child(path, key), "expected a string, found " + json_type_name(*it));
    return std::nullopt;
  }
  return it->get<std::string>();
}

namespace {
template <int N>
std::optional<Eigen::Matrix<double, N, 1>> read_vector(JsonInput& in, const nlohmann::json& object,
                                                       const std::string& path,
                                                       std::string_view key, bool required) {
  const std::string where = JsonInput::child(path, key);
  auto it = object.find(std::string(key));
  if (it == object.end()) {
    if (required) in.problem(where, "missing (an array of " + std::to_string(N) + " numbers)");
    return std::nullopt;
  }
  if (!it->is_array() || it->size() != N) {
    in.problem(where, "expected an array of " + std::to_string(N) + " numbers, found " +
                          json_type_name(*it));
    return std::nullopt;
  }
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) {
    const auto& e = (*it)[std::size_t(i)];
    if (!e.is_number() || !std::isfinite(e.get<double>())) {
      in.problem(JsonInput::child(where, std::size_t(i)),
                 "expected a finite number, found " + json_type_name(e));
      return std::nullopt;
    }
    v[i] = e.get<double>();
  }
  return v;
}
}  // namespace

std::optional<Eigen::Vector3d> JsonInput::vec3(const nlohmann::json& object,
                                               const std::string& path, std::string_view key,
                                               bool required) {
  return read_vector<3>(*this, object, path, key, required);
}

std::optional<Eigen::Vector2d> JsonInput::vec2(const nlohmann::json& object,
                                               const std::string& path, std::string_view key,
                                               bool required) {
  return read_vector<2>(*this, object, path, key, required);
}

}  // namespace upf
