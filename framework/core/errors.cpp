#include "framework/core/errors.h"

#include <sstream>

namespace upf {

namespace {
std::string describe(const std::vector<InputProblem>& problems) {
  std::ostringstream out;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    if (i) out << '\n';
    out << problems[i].where << ": " << problems[i].message;
  }
  return out.str();
}
}  // namespace

InputError::InputError(std::vector<InputProblem> problems)
    : std::runtime_error(describe(problems)), problems_(std::move(problems)) {}

InputError::InputError(std::string where, std::string message)
    : InputError(std::vector<InputProblem>{{std::move(where), std::move(message)}}) {}

InstabilityError::InstabilityError(std::uint64_t step_, double time_, std::uint32_t particle_id_,
                                   std::string quantity_, double value_, double limit_)
    : std::runtime_error([&] {
        std::ostringstream out;
        out << "unstable at step " << step_ << " (t = " << time_ << " s): particle id "
            << particle_id_ << " has " << quantity_ << " = " << value_;
        if (limit_ > 0) out << " (limit " << limit_ << ")";
        return out.str();
      }()),
      step(step_),
      time(time_),
      particle_id(particle_id_),
      quantity(std::move(quantity_)),
      value(value_),
      limit(limit_) {}

InstabilityError::InstabilityError(std::uint64_t step_, double time_, const std::string& what)
    : std::runtime_error("unstable at step " + std::to_string(step_) + " (t = " +
                         [&] {
                           std::ostringstream out;
                           out << time_;
                           return out.str();
                         }() +
                         " s): " + what),
      step(step_),
      time(time_),
      particle_id(0),
      quantity(what),
      value(0),
      limit(0) {}

}  // namespace upf
