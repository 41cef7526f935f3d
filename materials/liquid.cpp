#include "materials/liquid.h"

namespace upf {

MaterialKind liquid_material_kind() {
  return {
      "liquid",
      ParticleType::Liquid,
      "a fluid moved by an SPH-family solver (pcisph by default)",
      {
          {"density", "kg/m^3", 1000, 1, 1e5, "rest density rho0; particle mass is rho0 s^3"},
          {"viscosity", "m^2/s", 1e-3, 0, 10,
           "kinematic viscosity nu of the shared Laplacian viscosity (Monaghan 2005); also "
           "damps the flow, so it is larger than water's 1e-6 at coarse resolution; it limits "
           "the time step: dt <= 0.125 H^2 / nu"},
          {"boundary_viscosity", "m^2/s", 0, 0, 10,
           "kinematic viscosity against boundary particles (wall friction); 0 disables it"},
          {"surface_tension", "N/m", 0, 0, 10,
           "surface tension coefficient sigma (water 0.0728); 0 disables it; the model is "
           "\"surface_tension_model\", the wetting of walls and bodies \"adhesion\" "
           "(docs/surface-tension.md); it limits the time step: dt <= 0.25 sqrt(rho0 s^3 / (2 pi "
           "sigma))"},
          {"drag_viscosity", "Pa s", 1e-3, 1e-6, 1e3,
           "the liquid's physical dynamic viscosity mu, for the drag on grains (Di Felice "
           "1994); the SPH viscosity above is a numerical one"},
      },
      "pcisph",
  };
}

}  // namespace upf
