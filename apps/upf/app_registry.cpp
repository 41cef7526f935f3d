#include "app_registry.h"

#include "coupling/bodies/bodies_section.h"
#include "render/render_settings.h"

#include "solvers/register_builtin_solvers.h"

namespace upf::app {

Registry make_app_registry() {
  Registry registry;
  register_builtins(registry);
  register_coupling(registry);
  render::register_render_section(registry);
  register_extensions(registry);
  return registry;
}

}  // namespace upf::app
