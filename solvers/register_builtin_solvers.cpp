#include "solvers/register_builtin_solvers.h"

#include "materials/register_materials.h"
#include "solvers/pcisph/register_pcisph.h"

namespace upf {

void register_builtins(Registry& registry) {
  register_materials(registry);
  register_pcisph(registry);
}

}  // namespace upf
