#include "materials/liquid.h"

namespace upf {

MaterialKind liquid_material_kind() {
  return {
      "liquid",
      ParticleType::Liquid,
      "a fluid moved by an SPH-family solver (pcisph by default)",
      {
          {"density", "kg/m^3", 1000, 1, 1e5,
           "rest density rho0; particle mass is rho0 s^3; liquids of different density share one "
           "fluid solver, at ratios up to 10 (docs/multiphase.md)"},
          {"viscosity", "m^2/s", 1e-3, 0, 10,
           "kinematic viscosity nu of the shared Laplacian viscosity (Monaghan 2005); also "
           "damps the flow, so it is larger than water's 1e-6 at coarse resolution; it limits "
           "the time step: dt <= 0.07 s^2 / nu unless implicit_viscosity is 1"},
          {"implicit_viscosity", "1", 0, 0, 1,
           "1: the viscosity (and boundary_viscosity) is solved implicitly (Weiler et al. "
           "2018; docs/viscosity.md), so it no longer limits the time step: honey, lava, mud; "
           "0: explicit",
           true},
          {"viscosity_tolerance", "1", 1e-3, 1e-8, 0.5,
           "implicit viscosity: the conjugate gradient stops at this relative residual"},
          {"viscosity_max_iterations", "1", 100, 1, 10000,
           "implicit viscosity: iterations at most; a solve that needs more stops the run "
           "(exit 3, the last good frame written)",
           true},
          {"boundary_viscosity", "m^2/s", 0, 0, 10,
           "kinematic viscosity against boundary particles (wall friction); 0 disables it"},
          {"surface_tension", "N/m", 0, 0, 10,
           "surface tension coefficient sigma (water 0.0728); 0 disables it; the model is "
           "\"surface_tension_model\", the wetting of walls and bodies \"adhesion\" "
           "(docs/surface-tension.md); it limits the time step: dt <= 0.15 sqrt(rho0 s^3 / (2 pi "
           "sigma))"},
          {"drag_viscosity", "Pa s", 1e-3, 1e-6, 1e3,
           "the liquid's physical dynamic viscosity mu, for the drag on grains (Di Felice "
           "1994); the SPH viscosity above is a numerical one"},
      },
      "pcisph",
  };
}

}  // namespace upf
