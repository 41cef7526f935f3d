// Registers WCSPH (Becker & Teschner 2007) under the name "wcsph".
#pragma once

namespace upf {
class Registry;
void register_wcsph(Registry& registry);
}  // namespace upf
