// The force of a DEM solver's grains on each face of each container (the exact planes of
// dem_stages.h), averaged over the world step: what a load cell under a silo's floor or on its
// wall reads. Summed from the per-grain records of DemForcesStage (DemContactRecord) in fixed
// point, so the totals do not depend on the particles' order or the thread count, and a device
// pipeline's downloaded fields give the same bits.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "framework/core/vec3d.h"
#include "framework/particles/particles.h"
#include "framework/world/container_box.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

struct ContainerWallForces {
  // N, the grains' push on each face along its outward normal, in the order x_min, x_max,
  // y_min, y_max, z_min, z_max.
  std::array<double, 6> normal{};
  // N, the grains' tangential (friction) force on the container's faces, all faces together.
  Vec3d shear;
};

// The six faces' names, in ContainerWallForces::normal's order.
const std::array<const char*, 6>& container_face_names();

// Per container: the forces of the grains of `owns` on its faces. A grain counts for the first
// container whose box, widened by the grain's radius, holds its centre (a grain touches the faces
// of one container at a time unless containers touch). Forces from the per-grain step averages
// `wall_normal` and `wall_shear` (DemContactRecord); `radius` per particle.
std::vector<ContainerWallForces> container_wall_forces(const Particles& particles,
                                                       const std::vector<ContainerBox>& boxes,
                                                       OwnedMaterials owns, const Vec3* wall_normal,
                                                       const Vec3* wall_shear, const Real* radius);

// The table's columns: per container, "<face>_normal" for each face and "shear_x/y/z", prefixed
// with "container<c>." when the scene has more than one container.
std::vector<std::string> container_wall_columns(std::size_t containers);
// One row in container_wall_columns' order.
std::vector<double> container_wall_row(const std::vector<ContainerWallForces>& forces);

}  // namespace upf
