// upf's errors as Python exceptions (python/upf/errors.py defines the classes): a bad scene is a
// upf.SceneError (a ValueError) carrying every problem's JSON path or file; an instability is a
// upf.InstabilityError with the step, the particle and the quantity; failed output an OSError.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <exception>
#include <utility>

#include "bindings.h"
#include "framework/core/errors.h"

namespace py = pybind11;

namespace upf::python {

namespace {
// Raises cls(args...) as the pending Python exception.
template <class... Args>
void raise(const char* class_name, Args&&... args) {
  const py::object cls = py::module_::import("upf.errors").attr(class_name);
  PyErr_SetObject(cls.ptr(), cls(std::forward<Args>(args)...).ptr());
}
}  // namespace

void bind_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::list problems;
      for (const InputProblem& problem : e.problems())
        problems.append(py::make_tuple(problem.where, problem.message));
      raise("SceneError", e.what(), problems);
    } catch (const InstabilityError& e) {
      raise("InstabilityError", e.what(), e.step, e.time, e.particle_id, e.quantity, e.value,
            e.limit);
    } catch (const OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });
}

}  // namespace upf::python
