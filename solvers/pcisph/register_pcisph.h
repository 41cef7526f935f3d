// Registers PCISPH under the name "pcisph".
#pragma once

namespace upf {
class Registry;
void register_pcisph(Registry& registry);
}  // namespace upf
