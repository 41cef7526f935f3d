// The equilibrium contact angle a liquid reaches on a wall under Akinci et al. 2013's adhesion, as
// a function of the adhesion ratio beta / gamma, and its inverse: so a scene can ask for "90
// degrees on this body" (scene key "contact_angle") instead of a ratio.
//
// Measured, not derived: Young's equation with pair forces (cos theta = W_adhesion / sigma - 1)
// predicts 88 degrees at a ratio of 4, and drops reach 138 there. The table is a drop of 3 mm
// (6 spacings) resting on a wall under Akinci's cohesion and adhesion, its angle from the cap's
// height and volume averaged over 0.4 to 1.2 s (docs/surface-tension.md, "Contact angle"; the same
// drop at 8 spacings read 142 and 112 degrees at ratios 4 and 8 against 138 and 108.5). Beyond a
// ratio of about 11.5 the liquid wets completely: it runs up the walls as a film (ratio 12 did), so
// angles below about 85 degrees are out of this model's reach.
#pragma once

#include <array>
#include <utility>

namespace upf {

// (ratio, angle in degrees), the angle falling.
inline constexpr std::array<std::pair<double, double>, 7> kAdhesionContactAngles = {{
    {0.0, 180.0},
    {2.0, 149.0},
    {4.0, 138.0},
    {6.0, 121.0},
    {8.0, 108.5},
    {10.0, 94.5},
    {11.5, 85.0},
}};

// The angles a scene may ask for: the table's, from complete non-wetting down to the last angle
// measured before complete wetting.
inline constexpr double kSmallestContactAngle = 85.0;
inline constexpr double kLargestContactAngle = 180.0;

// The adhesion ratio whose drop rests at `degrees` (within [kSmallestContactAngle,
// kLargestContactAngle]): linear between the table's points.
inline double adhesion_ratio_for_contact_angle(double degrees) {
  const auto& t = kAdhesionContactAngles;
  for (std::size_t k = 1; k < t.size(); ++k)
    if (degrees >= t[k].second) {
      const double f = (t[k - 1].second - degrees) / (t[k - 1].second - t[k].second);
      return t[k - 1].first + f * (t[k].first - t[k - 1].first);
    }
  return t.back().first;
}

}  // namespace upf
