// Registers the built-in material kinds: liquid and frozen.
#pragma once

namespace upf {
class Registry;
void register_materials(Registry& registry);
}  // namespace upf
