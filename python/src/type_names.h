// Particle types by name for Python ("liquid", "rigid", ...): a list of names as a TypeMask.
#pragma once

#include <string>
#include <vector>

#include "framework/core/particle_type.h"

namespace upf::python {

// ValueError naming the argument and the allowed names for an unknown or empty list.
TypeMask type_mask(const std::vector<std::string>& names, const std::string& argument);

}  // namespace upf::python
