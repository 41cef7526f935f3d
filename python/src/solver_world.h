// What a Python solver sees of the world during one call (prepare, max_time_step, step): the
// particle arrays and fields as NumPy views without copies, neighbour lists, the coupling
// arrays, settings and materials. Valid only during that call: the world may reorder its arrays
// between calls, so a handle (and every view made from it) kept for later refuses to be used.
#pragma once

#include <string>

#include "framework/world/world.h"

namespace upf::python {

class SolverWorld {
 public:
  SolverWorld(World& world, std::string call) : world_(&world), call_(std::move(call)) {}
  // The world, if the call this handle was made for is still running; else an error naming it.
  World& world() const;
  bool valid() const { return world_ != nullptr; }
  void revoke() { world_ = nullptr; }

 private:
  World* world_;
  std::string call_;
};

}  // namespace upf::python
