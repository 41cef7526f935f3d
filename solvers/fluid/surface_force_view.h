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
  Akinci2013,             // cohesion + curvature (akinci_kernels.h)
  ContinuumSurfaceForce,  // Brackbill et al. 1992 (continuum_surface_force.h)
};

struct SurfaceForceView {
  SurfaceTensionModel model = SurfaceTensionModel::None;
  // Per material: the model's coefficient (0: no tension): Akinci's gamma, or the continuum
  // force's sigma / (c0 rho0) [m^3/s^2] (continuum_surface_force.h).
  const Real* cohesion = nullptr;
  // Per (liquid material, boundary material) pair, row-major over `materials`: Akinci's beta.
  const Real* adhesion = nullptr;
  std::uint32_t materials = 0;
  const Vec3* normal = nullptr;  // per particle, written by the density pass
  // Per particle, the continuum force's fitted curvature [1/m], 1 where it was fitted (else 0),
  // and the smoothed surface normal (continuum_surface_force.h's stages write them).
  const Real* curvature = nullptr;
  const Real* curvature_weight = nullptr;
  const Vec3* smoothed_normal = nullptr;
  bool has_adhesion = false;  // some pair has a positive beta

  UPF_HD bool on() const { return model != SurfaceTensionModel::None; }
  UPF_HD Real adhesion_between(std::uint32_t liquid, std::uint32_t boundary) const {
    return adhesion[liquid * materials + boundary];
  }
};

}  // namespace upf
