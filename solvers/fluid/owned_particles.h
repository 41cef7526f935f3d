// The particles one solver moves (those of its materials), as an index list rebuilt every step
// (reordering for locality moves them). Fluid and DEM solvers use it. Loops over the list split
// evenly between threads; a static split of all particles did not: walls and water sit in different
// parts of the Morton order, and one thread waited for the other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/executors/particle_range.h"
#include "framework/particles/particles.h"

namespace upf {

// A per-material "owned" flag array, by value in stages. C++17 and UPF_HD.
struct OwnedMaterials {
  const std::uint8_t* flags = nullptr;
  std::size_t count = 0;
  UPF_HD bool operator()(MaterialId m) const { return m < count && flags[m] != 0; }
};

class OwnedParticles {
 public:
  // Owns the particles of `materials`, out of `material_count` materials in the world.
  void set_materials(std::size_t material_count, const std::vector<MaterialId>& materials);
  // Collects the owned particles in index order.
  void rebuild(const Particles& particles);

  std::size_t size() const { return indices_.size(); }
  bool empty() const { return indices_.empty(); }
  std::uint32_t operator[](std::size_t k) const { return indices_[k]; }
  bool owns(MaterialId m) const { return m < owns_.size() && owns_[m] != 0; }

  // The owned particles, for CpuExecutor::run.
  ParticleRange range() const { return {indices_.data(), indices_.size()}; }
  // Which materials are owned, as a view a stage can hold.
  OwnedMaterials materials() const { return {owns_.data(), owns_.size()}; }

 private:
  std::vector<std::uint8_t> owns_;      // per material: moved by this solver
  std::vector<std::uint32_t> indices_;  // the particles moved, for the current step
};

}  // namespace upf
