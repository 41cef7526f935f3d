// The speed of sound a weakly compressible solver picks when the scene gives none. Density varies
// by about (v / c)^2 (Monaghan 1994), so Becker & Teschner 2007 take c = 10 v_max for about 1 %;
// v_max = sqrt(2 g H), H the height of the initial liquid, is the speed a column reaches by
// falling (free_fall_speed).
#pragma once

#include <string>
#include <vector>

#include "framework/core/real.h"
#include "framework/particles/particles.h"

namespace upf {

class World;

inline constexpr Real kSoundSpeedPerFlowSpeed = 10;

// 10 sqrt(2 g H). Throws InputError at /materials/<first of materials>/solver/<param> when the
// scene has no liquid column under gravity to derive it from.
Real automatic_sound_speed(const World& world, const std::vector<MaterialId>& materials,
                           const std::string& param);

}  // namespace upf
