// One colour per particle type, shared by every output that colours particles (the PLY point
// clouds now, a renderer later), so a liquid looks the same blue everywhere.
//
// Chosen to tell the types apart at a glance, also for red-green colour blindness: a saturated
// blue liquid against an orange rigid body, a pale sand for grains and a neutral grey for the
// static walls that frame the scene without drawing the eye.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "framework/core/particle_type.h"

namespace upf {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend constexpr bool operator==(const Rgb8&, const Rgb8&) = default;
};

// Indexed by the ParticleType value.
inline constexpr std::array<Rgb8, kParticleTypeCount> kTypePalette = {{
    {30, 110, 220},   // liquid: water blue
    {240, 140, 30},   // rigid: orange
    {215, 190, 130},  // granular: sand
    {150, 150, 150},  // frozen: grey
}};

// A type byte outside the enum (a corrupt array) shows up magenta rather than as a real type.
inline constexpr Rgb8 kUnknownTypeColour = {255, 0, 255};

constexpr Rgb8 type_colour(ParticleType t) {
  const auto i = static_cast<std::size_t>(t);
  return i < kTypePalette.size() ? kTypePalette[i] : kUnknownTypeColour;
}

}  // namespace upf
