// The particles a stage runs over. C++17 and UPF_HD, so device code can use it too.
#pragma once

#include <cstddef>
#include <cstdint>

#include "framework/core/real.h"

namespace upf {

// The particles a stage runs over: all of [0, size) when `indices` is null, else the listed ones.
struct ParticleRange {
  const std::uint32_t* indices = nullptr;
  std::size_t size = 0;

  UPF_HD std::uint32_t operator[](std::size_t k) const {
    return indices ? indices[k] : std::uint32_t(k);
  }
};

inline ParticleRange all_particles(std::size_t n) {
  return {nullptr, n};
}

}  // namespace upf
