#include "materials/granular.h"

namespace upf {

MaterialKind granular_material_kind() {
  return {
      "granular",
      ParticleType::Granular,
      "spherical grains (sand, gravel, glass beads) moved by DEM: dem_linear (Cundall & Strack "
      "1979 spring-dashpot, the default) or dem_hertz (Hertz-Mindlin)",
      {
          {"density", "kg/m^3", 2500, 1, 1e5, "density of the grain material (not the bulk)"},
          {"radius", "m", 0, 0, 1e3,
           "grain radius; 0 means half the particle spacing. At most the spacing"},
          {"youngs_modulus", "Pa", 5e6, 1e3, 1e13,
           "Young's modulus E (Hertz-Mindlin; real sand is ~1e10, softer runs with larger steps)"},
          {"poisson_ratio", "1", 0.3, 0, 0.49,
           "Poisson ratio nu (Hertz-Mindlin; both tangential "
           "stiffnesses)"},
          {"normal_stiffness", "N/m", 1e4, 1, 1e12, "spring constant k_n of the linear model"},
          {"restitution", "1", 0.5, 0.01, 1,
           "coefficient of restitution of a head-on impact; sets the normal damping"},
          {"friction", "1", 0.5, 0, 10, "sliding (Coulomb) friction coefficient mu"},
          {"wall_friction", "1", -1, -1, 10,
           "sliding friction coefficient of grains on container walls and bodies (a glass "
           "wall under sand); -1: the grain-grain friction"},
          {"rolling_friction", "1", 0, 0, 1,
           "rolling resistance coefficient mu_r: torque mu_r R* F_n against the relative rolling"},
          {"cohesion", "N/m", 0, 0, 10,
           "liquid-bridge cohesion (wet sand): attraction 2 pi R* gamma while grains touch "
           "(Willett et al. 2000, full bridge), gamma the surface tension"},
      },
      "dem_linear",
  };
}

}  // namespace upf
