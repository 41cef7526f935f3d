#include "solvers/fluid/owned_particles.h"

namespace upf {

void OwnedParticles::set_materials(std::size_t material_count,
                                   const std::vector<MaterialId>& materials) {
  owns_.assign(material_count, 0);
  for (MaterialId m : materials) owns_[m] = 1;
}

void OwnedParticles::rebuild(const Particles& particles) {
  indices_.clear();
  // Ghosts (other ranks' particles) are moved by their owners.
  for (std::size_t i = 0; i < particles.owned_size(); ++i)
    if (owns_[particles.material[i]]) indices_.push_back(std::uint32_t(i));
}

}  // namespace upf
