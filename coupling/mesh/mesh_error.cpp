#include "coupling/mesh/mesh_error.h"

#include <sstream>

namespace upf {

InputError mesh_error(const std::string& file, const std::string& where, const std::string& what) {
  return InputError(where.empty() ? file : where, "mesh file '" + file + "': " + what);
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace upf
