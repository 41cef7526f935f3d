// The registry the `upf` program runs with: the built-in materials and solvers, then every
// extension compiled in from outside the framework (see docs/extending.md).
#pragma once

#include "framework/solver/registry.h"

namespace upf::app {

Registry make_app_registry();

// Registers the extensions listed in UPF_EXTENSION_DIRS. Defined in a source file that CMake
// generates (cmake/UpfExtensions.cmake), so adding an extension edits nothing here.
void register_extensions(Registry& registry);

}  // namespace upf::app
