#include "framework/run/surface_memory.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "framework/core/errors.h"

namespace upf {

double surface_grid_bytes(std::size_t liquid_particles, double voxel_factor) {
  return 8.0 * double(liquid_particles) / (voxel_factor * voxel_factor * voxel_factor);
}

void check_surface_memory(const SceneDescription& scene, std::size_t liquid_particles) {
  const OutputDesc& output = scene.output;
  if (!(output.surface || output.surface_vdb)) return;
  const double bytes = surface_grid_bytes(liquid_particles, output.surface_voxel);
  const double bound = output.surface_memory_gb * 1e9;
  if (bytes <= bound) return;
  // The voxel at which the estimate meets the bound: bytes scale as 1 / voxel^3.
  const double fits = output.surface_voxel * std::cbrt(bytes / bound);
  char message[320];
  std::snprintf(message, sizeof message,
                "a surface voxel of %g spacings makes the liquid surface's grids take about %.3g "
                "GB for %zu liquid particles, more than /output/surface_memory (%g GB); a voxel "
                "of at least %.3g spacings fits, or raise the bound",
                output.surface_voxel, bytes / 1e9, liquid_particles, output.surface_memory_gb,
                fits);
  throw InputError(scene.source.string() + ":/output/surface_voxel", message);
}

}  // namespace upf
