// Reading JSON with every problem collected under its JSON path ("/materials/water/density"),
// so `upf validate` can list them all at once. Unknown keys get a did-you-mean suggestion.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/errors.h"
#include "framework/params/param_spec.h"

namespace upf {

// Closest candidate to `word` by edit distance, if it is close enough to be a likely typo.
std::optional<std::string> did_you_mean(std::string_view word,
                                        const std::vector<std::string>& candidates);

std::string json_type_name(const nlohmann::json& node);

class JsonInput {
 public:
  explicit JsonInput(std::vector<InputProblem>& problems) : problems_(problems) {}

  void problem(const std::string& path, const std::string& message) {
    problems_.push_back({path, message});
  }
  // No problem found so far.
  bool clean() const { return problems_.empty(); }
  static std::string child(const std::string& path, std::string_view key) {
    return path + "/" + std::string(key);
  }
  static std::string child(const std::string& path, std::size_t index) {
    return path + "/" + std::to_string(index);
  }

  // False (with a problem) when `node` is not an object.
  bool expect_object(const nlohmann::json& node, const std::string& path);
  // Calls visit(element, path) for each object element of the array at object[key] (absent: no
  // calls); a non-array or non-object element is reported.
  template <class Visit>
  void for_each_object(const nlohmann::json& object, const std::string& path, std::string_view key,
                       Visit&& visit) {
    auto it = object.find(std::string(key));
    if (it == object.end()) return;
    const std::string where = child(path, key);
    if (!it->is_array()) {
      problem(where, "expected an array, found " + json_type_name(*it));
      return;
    }
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string element_path = child(where, i);
      if (expect_object((*it)[i], element_path)) visit((*it)[i], element_path);
    }
  }

  // Reports every key of `object` not in `allowed`.
  void check_keys(const nlohmann::json& object, const std::string& path,
                  const std::vector<std::string>& allowed);

  // A number at object[key] within [lo, hi] (open at lo when `lo_open`), or `fallback` when the
  // key is absent. On a problem, reports it and returns the fallback.
  double number(const nlohmann::json& object, const std::string& path, std::string_view key,
                double fallback, double lo, double hi, bool lo_open = false,
                std::string_view unit = "");
  std::optional<double> required_number(const nlohmann::json& object, const std::string& path,
                                        std::string_view key, double lo, double hi,
                                        bool lo_open = false, std::string_view unit = "");
  // The number object[spec.name] checked against the spec's range, or `fallback` when absent.
  double number(const nlohmann::json& object, const std::string& path, const ParamSpec& spec,
                double fallback);
  std::optional<std::string> string(const nlohmann::json& object, const std::string& path,
                                    std::string_view key, bool required);
  std::optional<Eigen::Vector3d> vec3(const nlohmann::json& object, const std::string& path,
                                      std::string_view key, bool required);
  std::optional<Eigen::Vector2d> vec2(const nlohmann::json& object, const std::string& path,
                                      std::string_view key, bool required);

 private:
  std::vector<InputProblem>& problems_;
};

}  // namespace upf
