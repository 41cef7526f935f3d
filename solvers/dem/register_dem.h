#pragma once

namespace upf {

class Registry;

// The DEM solvers dem_linear and dem_hertz and the "granular_blocks" scene key.
void register_dem(Registry& registry);

}  // namespace upf
