// Typed parameter metadata: name, unit, default, allowed range and a description. The same
// table drives scene-file validation, `upf info` and the documentation, so they cannot disagree.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "framework/core/errors.h"

namespace upf {

struct ParamSpec {
  std::string name;
  std::string unit;  // SI, "1" for dimensionless
  double default_value = 0;
  double min_value = 0;  // inclusive, unless exclusive_min
  double max_value = 0;  // inclusive
  std::string description;
  bool integer = false;
  // Last, so that the brace-initialised tables that leave it out keep compiling: a step length or
  // a frame rate must be above its lower bound, not equal to it.
  bool exclusive_min = false;
};

// Parameter values by name, filled from defaults and overridden by the scene.
class ParamValues {
 public:
  ParamValues() = default;
  explicit ParamValues(const std::vector<ParamSpec>& specs);

  double get(const std::string& name) const;  // throws std::out_of_range for an unknown name
  void set(const std::string& name, double value) { values_[name] = value; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, double>& all() const { return values_; }

 private:
  std::map<std::string, double> values_;
};

const ParamSpec* find_spec(const std::vector<ParamSpec>& specs, const std::string& name);

// Checks `value` against `spec`; on failure appends a problem naming `where`, the value and the
// allowed range, and returns false.
bool check_param(const ParamSpec& spec, double value, const std::string& where,
                 std::vector<InputProblem>& problems);

}  // namespace upf
