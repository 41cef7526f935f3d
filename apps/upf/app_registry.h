// The registry the `upf` program runs with: the built-in materials and solvers, then every
// extension compiled in from outside the framework (see docs/extending.md).
#pragma once

#include "framework/solver/registry.h"

namespace upf::app {
Registry make_app_registry();
}  // namespace upf::app
