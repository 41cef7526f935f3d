// Names that become file or folder names (a scene's `name`, a compare run's name, a --vary
// label). Someone else's scene file must not be able to write outside the folder it was given,
// so a name is checked before it is joined to a path: one plain path component, nothing that a
// file system or a shell reads as a path or an option.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace upf {

// Why `name` cannot be one file name, or nothing when it can: empty, "." or "..", a separator
// ('/' or '\\'), a NUL or another control character, a leading '-' or longer than 200 bytes.
std::optional<std::string> file_name_problem(std::string_view name);

// Throws InputError(where, "...") naming the value and the rule when file_name_problem finds one.
void check_file_name(std::string_view name, const std::string& where);

}  // namespace upf
