#include "framework/particles/array_sizes.h"

#include <cstddef>
#include <stdexcept>

namespace upf {

void check_array_sizes(const Particles& particles, const std::string& who) {
  const std::size_t n = particles.size();
  const auto check = [&](const std::string& name, std::size_t values) {
    if (values != n) {
      throw std::logic_error(who + ": particle array '" + name + "' has " + std::to_string(values) +
                             " values for " + std::to_string(n) + " particles");
    }
  };
  check("velocity", particles.velocity.size());
  check("mass", particles.mass.size());
  check("type", particles.type.size());
  check("material", particles.material.size());
  check("id", particles.id.size());
  check("body", particles.body.size());
  check("boundary_volume", particles.boundary_volume.size());
  for (const auto& [name, field] : particles.scalar_fields()) check(name, field.values.size());
  for (const auto& [name, field] : particles.vector_fields()) check(name, field.values.size());
}

}  // namespace upf
