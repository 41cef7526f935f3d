// NumPy arrays over the world's particle arrays without copies. Each array's base is `owner`,
// which keeps the memory's owner alive; whether the memory is still the particles' is for the
// caller's guard (a Simulation's generation, a SolverWorld's call) to say.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "framework/particles/particles.h"

namespace upf::python {

// Built-in arrays that Python may write: the state a user sets up or nudges. The others (id,
// type, material, body, boundary_volume) route particles and pair them with bodies: read-only.
inline bool writable_builtin(const std::string& name) {
  return name == "position" || name == "velocity" || name == "mass";
}

// The names particle_array() knows: the built-ins, then every named field.
std::vector<std::string> particle_array_names(const Particles& particles);

// A view of the built-in array or named field `name`: shape (n,) or (n, 3). KeyError (listing
// the names there are) for an unknown name.
pybind11::array particle_array(Particles& particles, const std::string& name,
                               pybind11::handle owner);

// A read-only view of an index array (neighbour offsets and indices).
pybind11::array index_view(const std::vector<std::uint32_t>& values, pybind11::handle owner);

// A (n, 3) view of a coupling or other Vec3 array.
pybind11::array vector_view(std::vector<Vec3>& values, pybind11::handle owner, bool writable);

}  // namespace upf::python
