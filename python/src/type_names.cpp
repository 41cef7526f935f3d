#include "type_names.h"

#include <pybind11/pybind11.h>

namespace upf::python {

TypeMask type_mask(const std::vector<std::string>& names, const std::string& argument) {
  if (names.empty())
    throw pybind11::value_error(
        argument + ": name at least one particle type (liquid, rigid, granular, frozen)");
  TypeMask mask = 0;
  for (const std::string& n : names) {
    const auto t = parse_particle_type(n);
    if (!t)
      throw pybind11::value_error(argument + ": unknown particle type '" + n +
                                  "' (allowed: liquid, rigid, granular, frozen)");
    mask = TypeMask(mask | mask_of(*t));
  }
  return mask;
}

}  // namespace upf::python
