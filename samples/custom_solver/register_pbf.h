// Registers Position Based Fluids under the name "pbf". The `upf` program calls this through
// upf_add_extension(... REGISTER upf::pbf::register_pbf) in this folder's CMakeLists.txt.
#pragma once

namespace upf {
class Registry;
}

namespace upf::pbf {
void register_pbf(Registry& registry);
}  // namespace upf::pbf
