#include "solvers/fluid/sound_speed.h"

#include "framework/core/errors.h"
#include "framework/world/world.h"
#include "solvers/fluid/fluid_time_step.h"

namespace upf {

Real automatic_sound_speed(const World& world, const std::vector<MaterialId>& materials,
                           const std::string& param) {
  const Real c = kSoundSpeedPerFlowSpeed * free_fall_speed(world);
  if (c <= 0 && !materials.empty())
    throw InputError("/materials/" + world.materials()[materials.front()].name + "/solver/" + param,
                     param +
                         " = 0 derives it from gravity and the height of the liquid, and this "
                         "scene has no liquid column under gravity: give " +
                         param + " > 0");
  return c;
}

}  // namespace upf
