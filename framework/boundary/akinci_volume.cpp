#include "framework/boundary/akinci_volume.h"

namespace upf {

void compute_boundary_volumes(Particles& particles, TypeMask boundary,
                              const NeighbourList& boundary_neighbours,
                              const CubicSplineKernel& kernel, const CpuExecutor& exec) {
  const Vec3* x = particles.position.data();
  const std::vector<Real>* known = particles.find_scalar(kKnownBoundaryVolumeField);
  exec.for_each(particles.size(), [&](std::size_t b) {
    if (!in_mask(boundary, particles.type[b])) return;
    if (known && (*known)[b] > 0) {
      particles.boundary_volume[b] = (*known)[b];
      return;
    }
    Real sum = kernel.value(Real(0));
    for (std::uint32_t k : boundary_neighbours.of(b)) sum += kernel.value(x[b] - x[k]);
    particles.boundary_volume[b] = Real(1) / sum;
  });
}

}  // namespace upf
