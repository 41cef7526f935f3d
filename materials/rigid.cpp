#include "materials/rigid.h"

namespace upf {

std::vector<ParamSpec> contact_params() {
  return {
      {"friction", "1", 0.5, 0, 10, "Coulomb friction coefficient of body contacts (Bullet)"},
      {"restitution", "1", 0.1, 0, 1, "restitution coefficient of body contacts (Bullet)"},
      {"free_slip", "1", 0, 0, 1,
       "1: liquid slides along this boundary without friction; a liquid's boundary_viscosity "
       "damps its motion into and off the surface and its particles' jitter, not its sliding "
       "(Adami et al. 2012 free-slip wall; explicit viscosity only; docs/viscosity.md); 0: "
       "no-slip",
       true},
  };
}

MaterialKind rigid_material_kind() {
  std::vector<ParamSpec> params = {
      {"density", "kg/m^3", 1000, 1, 1e5,
       "density of the body: mass and inertia follow from the closed mesh"},
  };
  for (auto& p : contact_params()) params.push_back(p);
  return {
      "rigid",
      ParticleType::Rigid,
      "a rigid body from a closed mesh, moved by Bullet and coupled two-way with fluids through "
      "boundary particles on its surface (Akinci et al. 2012)",
      params,
      "",
  };
}

}  // namespace upf
