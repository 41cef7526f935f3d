// What the shared surface forces (surface_forces.h) read besides the particles: the model of the
// solver's liquids, per material its cohesion coefficient, per pair of materials the adhesion
// coefficient, and per particle the field the density pass wrote (Akinci's normals). Plain
// pointers, so that the CPU and the device pipeline share it. A second model would add its
// enumerator and its coefficient's meaning here (docs/surface-tension.md lists those tried).
#pragma once

#include <cstdint>

#include "framework/core/vec3.h"

namespace upf {

enum class SurfaceTensionModel : std::uint8_t {
  None,
  Akinci2013,  // cohesion + curvature (akinci_kernels.h)
};

struct SurfaceForceView {
  SurfaceTensionModel model = SurfaceTensionModel::None;
  // Per material: the model's coefficient, Akinci's gamma (0: no tension).
  const Real* cohesion = nullptr;
  // Per (liquid material, boundary material) pair, row-major over `materials`: Akinci's beta.
  const Real* adhesion = nullptr;
  std::uint32_t materials = 0;
  const Vec3* normal = nullptr;  // per particle, written by the density pass
  bool has_adhesion = false;     // some pair has a positive beta

  UPF_HD bool on() const { return model != SurfaceTensionModel::None; }
  UPF_HD Real adhesion_between(std::uint32_t liquid, std::uint32_t boundary) const {
    return adhesion[liquid * materials + boundary];
  }
};

}  // namespace upf
