// Registers DFSPH under the name "dfsph".
#pragma once

namespace upf {
class Registry;
void register_dfsph(Registry& registry);
}  // namespace upf
