// Fields through which one solver pushes another solver's particles within a step.
#pragma once

namespace upf {

// Force (N) on liquid particles from other materials in this step (the reaction of the drag and
// buoyancy on grains). Written in full by the solver that creates it, which runs before the
// fluid solvers (granular solvers step first); fluid solvers add f / m to the non-pressure
// acceleration.
inline constexpr const char* kLiquidCouplingForceField = "liquid_coupling_force";

}  // namespace upf
