// Reading an array of objects from a scene, each element at its own JSON path, for the
// sections whose key holds a list (emitters, sinks).
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "framework/scene/json_input.h"

namespace upf {

// Calls read_one(element, path, index) for each element of the array `node` (each must be an
// object); false when any element (or the array itself) was reported.
template <class ReadOne>
bool read_each(const nlohmann::json& node, const std::string& path, JsonInput& in, const char* what,
               ReadOne&& read_one) {
  if (!node.is_array()) {
    in.problem(path,
               std::string("expected an array of ") + what + ", found " + json_type_name(node));
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string where = JsonInput::child(path, i);
    ok = in.expect_object(node[i], where) && read_one(node[i], where, i) && ok;
  }
  return ok;
}

}  // namespace upf
