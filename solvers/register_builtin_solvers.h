// Registers every built-in material kind and solver into a registry.
#pragma once

namespace upf {
class Registry;
// Material kinds (materials/) and solvers (solvers/*/): what `upf` and the tests start from.
void register_builtins(Registry& registry);
}  // namespace upf
