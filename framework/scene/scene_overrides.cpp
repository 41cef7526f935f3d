#include "framework/scene/scene_overrides.h"

#include "framework/core/errors.h"

namespace upf {

namespace {
using json = nlohmann::json;

std::string where(const SceneOverride& o) {
  return "--set " + o.given;
}

// The value at `parent`, or an InputError naming the --set: the JSON library throws its own
// errors for some pointers (an index beyond size_t, a leading zero) instead of answering false.
json& container_at(json& document, const json::json_pointer& parent, const SceneOverride& o) {
  const std::string missing = "the scene has no " + parent.to_string() + " to set a value in";
  try {
    if (!document.contains(parent)) throw InputError(where(o), missing);
    return document.at(parent);
  } catch (const json::exception&) {
    throw InputError(where(o), missing);
  }
}
}  // namespace

SceneOverride parse_override(const std::string& argument) {
  const std::string at = "--set " + argument;
  const std::size_t equals = argument.find('=');
  if (equals == std::string::npos)
    throw InputError(at, "expected POINTER=VALUE, e.g. /materials/water/viscosity=0.01");
  SceneOverride o;
  o.given = argument;
  try {
    o.pointer = json::json_pointer(argument.substr(0, equals));
  } catch (const json::exception&) {
    throw InputError(at, "'" + argument.substr(0, equals) +
                             "' is not a JSON pointer: it starts with '/' and names keys and "
                             "indices, e.g. /materials/water/viscosity or /fluid_blocks/0/max");
  }
  if (o.pointer.empty()) throw InputError(at, "the pointer must name a value inside the scene");
  const std::string text = argument.substr(equals + 1);
  try {
    o.value = json::parse(text);
  } catch (const json::out_of_range&) {
    // 1e400 is JSON, but no double holds it: taken as a string, it became "expected a number,
    // found a string", blamed on the scene file.
    throw InputError(at, "'" + text +
                             "' holds a number out of the representable range: a double holds "
                             "magnitudes up to about 1.8e308");
  } catch (const json::exception&) {
    o.value = text;  // not JSON: the text itself, as a string
  }
  return o;
}

void apply_overrides(json& document, const std::vector<SceneOverride>& overrides) {
  for (const SceneOverride& o : overrides) {
    const json::json_pointer parent = o.pointer.parent_pointer();
    json& container = container_at(document, parent, o);
    const std::string& key = o.pointer.back();
    if (container.is_object()) {
      container[key] = o.value;
    } else if (container.is_array()) {
      std::size_t index = 0;
      try {
        std::size_t used = 0;
        index = std::stoul(key, &used);
        if (used != key.size()) throw std::invalid_argument(key);
      } catch (const std::exception&) {
        throw InputError(where(o),
                         parent.to_string() + " is an array: '" + key + "' is not an index");
      }
      if (index >= container.size())
        throw InputError(where(o), parent.to_string() + " has " + std::to_string(container.size()) +
                                       (container.size() == 1 ? " entry" : " entries") +
                                       ": no index " + key);
      container[index] = o.value;
    } else {
      throw InputError(where(o), parent.to_string() + " is a " + container.type_name() +
                                     ", not an object or array");
    }
  }
}

}  // namespace upf
