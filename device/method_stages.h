// The stage layout of a pressure method in the device pipeline (fluid_part.h). Most methods
// run "non_pressure", "pressure" and "integration" with symplectic Euler over a_other +
// a_pressure, and derive from ThreeStageMethod; one with a "divergence" stage between
// "non_pressure" and "pressure", or with its own integration (DFSPH), sets the flags itself.
#pragma once

namespace upf::device {

struct ThreeStageMethod {
  static constexpr bool kDivergenceStage = false;
  static constexpr bool kOwnIntegration = false;
};

}  // namespace upf::device
