// The error classes every layer throws, each mapped to the command-line exit code a user sees.
// Nothing in upf calls abort(): errors travel as exceptions up to the program's entry point.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace upf {

enum class ExitCode : int { Ok = 0, Failure = 1, BadInput = 2, Unstable = 3, Interrupted = 130 };

// One problem found in user input: where (JSON path or file) and what.
struct InputProblem {
  std::string where;
  std::string message;
};

// Bad input: a malformed scene, a missing file, an out-of-range parameter. Exit code 2.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<InputProblem> problems);
  InputError(std::string where, std::string message);
  const std::vector<InputProblem>& problems() const { return problems_; }

 private:
  std::vector<InputProblem> problems_;
};

// The simulation blew up: the step, the particle and the quantity that went bad. Exit code 3.
class InstabilityError : public std::runtime_error {
 public:
  InstabilityError(std::uint64_t step, double time, std::uint32_t particle_id, std::string quantity,
                   double value, double limit);
  // A failure no one particle stands for (a solve that did not converge): `what` says which.
  InstabilityError(std::uint64_t step, double time, const std::string& what);
  std::uint64_t step;
  double time;
  std::uint32_t particle_id;
  std::string quantity;
  double value;
  double limit;
};

// An iterative solve (implicit viscosity) that did not reach its tolerance within its iteration
// cap. World::step reports it as an InstabilityError with the step and time: exit code 3.
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writing output failed (disk full, unwritable directory). Exit code 1.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace upf
