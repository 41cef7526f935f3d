#include "framework/core/file_name.h"

#include "framework/core/errors.h"

namespace upf {

std::optional<std::string> file_name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name == "." || name == "..") return "is '" + std::string(name) + "', a folder's alias";
  if (name.size() > 200) return "is longer than 200 bytes";
  if (name.front() == '-') return "starts with '-', which commands read as an option";
  for (const char c : name) {
    if (c == '/' || c == '\\') return "holds a path separator ('" + std::string(1, c) + "')";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "holds a control character";
  }
  return std::nullopt;
}

void check_file_name(std::string_view name, const std::string& where) {
  if (auto problem = file_name_problem(name))
    throw InputError(where, "'" + std::string(name) + "' " + *problem +
                                ": a name becomes a file name, so it must be one plain name "
                                "(no '/', '\\', '..', control characters or leading '-')");
}

}  // namespace upf
