// Registers SPH (Müller et al. 2003) under the name "sph".
#pragma once

namespace upf {
class Registry;
void register_sph(Registry& registry);
}  // namespace upf
