#include "materials/frozen.h"

namespace upf {

MaterialKind frozen_material_kind() {
  return {
      "frozen",
      ParticleType::Frozen,
      "static boundary particles with Akinci et al. 2012 volumes; nothing moves them",
      {},
      "",
  };
}

}  // namespace upf
