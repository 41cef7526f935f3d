// Errors about a mesh always name its file, and the JSON path that asked for it when there is one.
#pragma once

#include <string>

#include "framework/core/errors.h"

namespace upf {

// InputError at `where` (a JSON path such as "/bodies/0/mesh"; empty: the file itself) saying
// "mesh file '<file>': <what>".
InputError mesh_error(const std::string& file, const std::string& where, const std::string& what);

// A number as people write it: 6 significant digits, no trailing zeros ("0.001", "1e-05").
std::string format_number(double value);

}  // namespace upf
