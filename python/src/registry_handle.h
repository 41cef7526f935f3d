// A registry shared between Python and the simulations made with it: a simulation keeps the
// registry its solvers came from alive (Python solvers' factories live there).
#pragma once

#include <memory>

#include "framework/solver/registry.h"

namespace upf::python {

struct RegistryHandle {
  std::shared_ptr<Registry> registry;
};

}  // namespace upf::python
