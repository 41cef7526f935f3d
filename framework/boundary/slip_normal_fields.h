// The names of the free-slip normal fields (slip_normal.h), apart, so device code can name them.
#pragma once

namespace upf {

// World-frame unit normal of each free-slip boundary particle (zero elsewhere): read by the
// viscous wall velocity. Body particles get theirs from kBodySlipNormalField every step
// (PlaceBodyParticlesStage).
inline constexpr const char* kSlipNormalField = "boundary.slip_normal";
// The same in the body's frame, for body particles.
inline constexpr const char* kBodySlipNormalField = "body.local_slip_normal";

}  // namespace upf
