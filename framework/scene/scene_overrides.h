// Overrides of a scene's values from the command line, by JSON pointer (RFC 6901), as
// SPlisHSPlasH users set parameters without editing the file:
//   upf run SCENE --set /materials/water/viscosity=0.01 --set /time/end=2
// The value is JSON ("0.01", "[0, -9.81, 0]", "\"pcisph\""); text that is not JSON is a string
// (--set /materials/water/solver/name=dfsph). The overridden document is then read and checked
// like the file, so a bad value is reported with its JSON path, and the run records the scene
// as it ran (scene.json, the checkpoint's header).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace upf {

struct SceneOverride {
  std::string given;  // the argument as written, for messages: "/time/end=2"
  nlohmann::json::json_pointer pointer;
  nlohmann::json value;
};

// "POINTER=VALUE". InputError naming "--set ARG" for a missing '=', a malformed pointer or a
// number no double holds (1e400).
SceneOverride parse_override(const std::string& argument);

// Sets every override in order. The pointer's parent must exist: an object (the key is set or
// added) or an array (the index must exist). Otherwise an InputError naming "--set ARG" and the
// part of the pointer that is missing. The whole document (pointer "") cannot be replaced.
void apply_overrides(nlohmann::json& document, const std::vector<SceneOverride>& overrides);

}  // namespace upf
