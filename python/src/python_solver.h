// A solver written in Python, registered by name like any C++ solver (Registry::add_solver), so
// scenes name it and `upf.compare` runs it beside the built-ins. The adapter holds the Python
// object and forwards the Solver interface to its methods (prepare, max_time_step, step, stats),
// each with a SolverWorld valid for that call. It holds the object rather than being a pybind11
// trampoline subclass: the world owns its solvers through unique_ptr, and a trampoline's Python
// half would die with its last Python reference while the world still steps it.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "framework/solver/solver.h"

namespace upf::python {

class PythonSolver final : public Solver {
 public:
  PythonSolver(std::string name, pybind11::object solver);
  ~PythonSolver() override;
  PythonSolver(const PythonSolver&) = delete;
  PythonSolver& operator=(const PythonSolver&) = delete;

  std::string_view name() const override { return name_; }
  void prepare(World& world) override;
  Real max_time_step(const World& world) const override;
  std::vector<std::string> stages() const override { return {name_}; }
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override;
  // Its step is one call into Python: values it writes are not refreshed on the ghosts between
  // the loops inside it, and its arrays hold the ghosts too.
  std::string cannot_split() const override { return kWholeStepInPython; }
  std::string cannot_hold_images() const override { return kWholeStepInPython; }

 private:
  static constexpr const char* kWholeStepInPython =
      "a Python solver's step is one stage, so the ghosts that hold periodic images or other "
      "ranks' particles would keep stale values between its passes; run it without "
      "\"periodic\" and on one rank";
  std::string name_;
  pybind11::object solver_;
};

}  // namespace upf::python
