#include "framework/boundary/akinci_volume.h"

#include <cmath>

namespace upf {

void compute_boundary_volumes(Particles& particles, TypeMask boundary,
                              const NeighbourList& boundary_neighbours,
                              const CubicSplineKernel& kernel, const CpuExecutor& exec) {
  const Vec3* x = particles.position.data();
  const std::vector<Real>* scale = particles.find_scalar(kBoundaryVolumeScaleField);
  exec.for_each(particles.size(), [&](std::size_t b) {
    if (!in_mask(boundary, particles.type[b])) return;
    Real sum = kernel.value(Real(0));
    for (std::uint32_t k : boundary_neighbours.of(b)) sum += kernel.value(x[b] - x[k]);
    particles.boundary_volume[b] = (scale ? (*scale)[b] : Real(1)) / sum;
  });
}

}  // namespace upf

namespace upf {

Real wall_volume_scale(const CubicSplineKernel& kernel, Real spacing, int layers) {
  const int reach = int(std::ceil(kernel.support_radius() / spacing)) + 1;
  // Akinci volume of a wall particle in layer `l` (0 = fluid-facing) of an infinite flat slab.
  auto slab_volume = [&](int l) {
    double sum = 0;
    for (int k = 0; k < layers; ++k)
      for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j)
          sum += double(kernel.value(Vec3{Real(i) * spacing, Real(j) * spacing,
                                          Real(k - l) * spacing}));
    return 1.0 / sum;
  };
  // A fluid particle one spacing above the wall's first layer (z = 0 is the particle).
  double missing = 0, boundary = 0;
  const double cell = double(spacing) * spacing * spacing;
  for (int k = 1; k <= reach; ++k)
    for (int i = -reach; i <= reach; ++i)
      for (int j = -reach; j <= reach; ++j) {
        const double w = double(kernel.value(Vec3{Real(i) * spacing, Real(j) * spacing,
                                                  -Real(k) * spacing}));
        missing += w * cell;
        if (k <= layers) boundary += w * slab_volume(k - 1);
      }
  return boundary > 0 ? Real(missing / boundary) : Real(1);
}

}  // namespace upf
