#include "materials/register_materials.h"

#include "framework/solver/registry.h"
#include "materials/frozen.h"
#include "materials/granular.h"
#include "materials/liquid.h"
#include "materials/rigid.h"

namespace upf {

void register_materials(Registry& registry) {
  registry.add_material_kind(liquid_material_kind());
  registry.add_material_kind(frozen_material_kind());
  registry.add_material_kind(rigid_material_kind());
  registry.add_material_kind(granular_material_kind());
}

}  // namespace upf
