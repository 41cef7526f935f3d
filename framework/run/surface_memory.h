// A bound on the memory the liquid surface's grids take per frame ("surface" and "surface_vdb"
// formats, framework/output/liquid_surface.h), checked before the first step.
#pragma once

#include <cstddef>

#include "framework/scene/scene.h"

namespace upf {

// The bytes the surfacing of `liquid_particles` takes at a voxel of `voxel_factor` particle
// spacings: the anisotropic kernels' sums fill every voxel of the liquid's volume (N h^3, i.e.
// N / voxel_factor^3 voxels) and of the band around it, at 4 bytes a value and about as much
// again for the band, the tree and the level set rebuilt from it: 8 bytes a voxel of the volume.
double surface_grid_bytes(std::size_t liquid_particles, double voxel_factor);

// When the scene writes "surface" or "surface_vdb": an InputError at /output/surface_voxel
// (naming the estimate, the bound /output/surface_memory and the voxel that would fit) if the
// surfacing of `liquid_particles` would take more than the bound. Emitted liquid is not counted.
void check_surface_memory(const SceneDescription& scene, std::size_t liquid_particles);

}  // namespace upf
