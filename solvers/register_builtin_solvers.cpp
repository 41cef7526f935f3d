#include "solvers/register_builtin_solvers.h"

#include "materials/register_materials.h"
#include "solvers/dem/register_dem.h"
#include "solvers/dfsph/register_dfsph.h"
#include "solvers/fluid/surface_tension_models.h"
#include "solvers/iisph/register_iisph.h"
#include "solvers/pcisph/register_pcisph.h"
#include "solvers/sources/sources_section.h"
#include "solvers/sph/register_sph.h"
#include "solvers/wcsph/register_wcsph.h"

namespace upf {

void register_builtins(Registry& registry) {
  register_materials(registry);
  register_surface_tension_models(registry);
  register_pcisph(registry);
  register_sph(registry);
  register_wcsph(registry);
  register_dfsph(registry);
  register_iisph(registry);
  register_dem(registry);
  register_sources(registry);
}

}  // namespace upf
