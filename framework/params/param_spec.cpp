#include "framework/params/param_spec.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace upf {

ParamValues::ParamValues(const std::vector<ParamSpec>& specs) {
  for (const auto& s : specs) values_[s.name] = s.default_value;
}

double ParamValues::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::out_of_range("no parameter named '" + name + "'");
  return it->second;
}

const ParamSpec* find_spec(const std::vector<ParamSpec>& specs, const std::string& name) {
  for (const auto& s : specs)
    if (s.name == name) return &s;
  return nullptr;
}

bool check_param(const ParamSpec& spec, double value, const std::string& where,
                 std::vector<InputProblem>& problems) {
  std::ostringstream msg;
  const bool low = spec.exclusive_min ? !(value > spec.min_value) : value < spec.min_value;
  if (!std::isfinite(value) || low || value > spec.max_value) {
    msg << spec.name << " = " << value << " is out of range " << (spec.exclusive_min ? "(" : "[")
        << spec.min_value << ", " << spec.max_value << "]";
    if (!spec.unit.empty() && spec.unit != "1") msg << " " << spec.unit;
    problems.push_back({where, msg.str()});
    return false;
  }
  if (spec.integer && std::floor(value) != value) {
    msg << spec.name << " = " << value << " must be a whole number";
    problems.push_back({where, msg.str()});
    return false;
  }
  return true;
}

}  // namespace upf
