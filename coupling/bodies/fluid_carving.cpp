#include "coupling/bodies/fluid_carving.h"

#include <vector>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mesh_inside_test.h"
#include "coupling/sampling/sample_grid.h"
#include "framework/core/vec3_eigen.h"

namespace upf {

std::size_t carve_fluid(Particles& particles, const BodySource& body, double spacing) {
  const double skin = 0.5 * spacing;
  // The mesh surface: each outer-layer sample moved back out to it along its normal.
  SampleGrid surface(2 * skin);
  for (std::size_t k = 0; k < body.samples.size(); ++k)
    if (!body.normals[k].isZero()) surface.insert(body.samples[k] + skin * body.normals[k]);
  const bool closed = is_closed(body.mesh);
  const MeshInsideTest inside(body.mesh, spacing);
  Eigen::AlignedBox3d reach = bounding_box(body.mesh);
  reach.extend(reach.min() - Eigen::Vector3d::Constant(skin));
  reach.extend(reach.max() + Eigen::Vector3d::Constant(skin));

  std::vector<std::uint8_t> doomed(particles.size(), 0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.type[i] != ParticleType::Liquid) continue;
    const Eigen::Vector3d x = to_eigen(particles.position[i]);
    if (!reach.contains(x)) continue;
    if ((closed && inside.contains(x)) || surface.any_within(x, skin)) {
      doomed[i] = 1;
      ++count;
    }
  }
  particles.remove(doomed);
  return count;
}

}  // namespace upf
