// Registers IISPH under the name "iisph".
#pragma once

namespace upf {
class Registry;
void register_iisph(Registry& registry);
}  // namespace upf
