#include "materials/frozen.h"

#include "materials/rigid.h"

namespace upf {

MaterialKind frozen_material_kind() {
  return {
      "frozen",
      ParticleType::Frozen,
      "boundary particles with Akinci et al. 2012 volumes: container walls, and static or "
      "kinematic (prescribed motion) obstacles from meshes; no force moves them",
      contact_params(),
      "",
  };
}

}  // namespace upf
