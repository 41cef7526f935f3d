#include "framework/scene/viscosity_keys.h"

namespace upf {

void check_viscosity_keys(JsonInput& in, const SceneDescription& scene) {
  for (std::size_t a = 0; a < scene.materials.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      const Material &ma = scene.materials[a], &mb = scene.materials[b];
      if (ma.type != ParticleType::Liquid || mb.type != ParticleType::Liquid) continue;
      if (ma.solver != mb.solver) continue;
      const bool implicit_a = ma.param("implicit_viscosity") > 0;
      const bool implicit_b = mb.param("implicit_viscosity") > 0;
      if (implicit_a == implicit_b) continue;
      in.problem("/materials/" + ma.name + "/implicit_viscosity",
                 std::string(implicit_a ? "1" : "0") + " differs from material '" + mb.name +
                     "''s " + (implicit_b ? "1" : "0") + "; liquids moved by one solver ('" +
                     ma.solver + "') share one viscous solve: set both to the same value");
    }
}

}  // namespace upf
