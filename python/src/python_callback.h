// Calls into Python from inside a step (a force, a solver's methods). Ctrl-C reaches a running
// step only there: Python raises KeyboardInterrupt at the next bytecode a callback runs. It
// travels up as CallbackInterrupted, so that Simulation can tell it from a callback's own error
// (which leaves the world half-stepped) and put back the state from before the step; it is still
// an error_already_set, so Python sees the KeyboardInterrupt itself.
#pragma once

#include <pybind11/pybind11.h>

#include <utility>

namespace upf::python {

class CallbackInterrupted : public pybind11::error_already_set {
 public:
  explicit CallbackInterrupted(const pybind11::error_already_set& e)
      : pybind11::error_already_set(e) {}
};

// call() with the GIL held; a KeyboardInterrupt out of it becomes CallbackInterrupted.
template <class Call>
decltype(auto) call_python(Call&& call) {
  try {
    return std::forward<Call>(call)();
  } catch (pybind11::error_already_set& e) {
    if (e.matches(PyExc_KeyboardInterrupt)) throw CallbackInterrupted(e);
    throw;
  }
}

}  // namespace upf::python
