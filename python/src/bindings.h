// The parts of the module `_upf`, one function per concept (module.cpp calls them in order).
#pragma once

#include <pybind11/pybind11.h>

namespace upf::python {

void bind_errors(pybind11::module_& m);
void bind_registry(pybind11::module_& m);
void bind_solver_world(pybind11::module_& m);
void bind_simulation(pybind11::module_& m);

}  // namespace upf::python
