// The compiled half of the Python package `upf` (python/upf/__init__.py is the other): scenes,
// steps, runs and comparisons over the same library as the `upf` program (DESIGN.md, "Python").
#include "bindings.h"

PYBIND11_MODULE(_upf, m) {
  m.doc() = "upf's compiled core; use the package `upf`";
  upf::python::bind_errors(m);
  upf::python::bind_registry(m);
  upf::python::bind_solver_world(m);
  upf::python::bind_simulation(m);
}
