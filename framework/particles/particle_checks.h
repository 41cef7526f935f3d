// The per-particle values behind the world's reductions over speed and state, shared by the CPU
// executor (World) and the device pipeline (device/solver_pipeline.h), so both reduce the same
// values: the solvers' time-step limits and the stability check. C++17 and UPF_HD.
#pragma once

#include <cstddef>
#include <cstdint>

#include "framework/core/vec3.h"
#include "framework/particles/particles.h"

namespace upf {

// |v_i|^2 of a liquid particle, 0 for the others.
struct LiquidSpeedSquared {
  const Vec3* v;
  const ParticleType* type;
  UPF_HD Real operator()(std::uint32_t i) const {
    return type[i] == ParticleType::Liquid ? squared_norm(v[i]) : Real(0);
  }
};

// |v_i|^2 of a particle of type `of` whose material m has flags[m] != 0 (m below count), 0 for
// the others.
struct SpeedSquaredOf {
  const Vec3* v;
  const ParticleType* type;
  const MaterialId* material;
  ParticleType of;
  const std::uint8_t* flags;
  std::size_t count;
  UPF_HD Real operator()(std::uint32_t i) const {
    return type[i] == of && material[i] < count && flags[material[i]] != 0 ? squared_norm(v[i])
                                                                           : Real(0);
  }
};

// A particle whose state went bad: a position or velocity that is not finite, or a runaway speed.
struct BrokenParticle {
  const Vec3* x;
  const Vec3* v;
  double limit2;
  UPF_HD bool operator()(std::uint32_t i) const {
    return !is_finite(x[i]) || !is_finite(v[i]) || double(squared_norm(v[i])) > limit2;
  }
};

}  // namespace upf
