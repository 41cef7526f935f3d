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
    // A body's particles see only their own body, so a body's sampling, and its volumes, stay the
    // same as it moves past walls and other bodies; walls (no body) see walls.
    const BodyId own = particles.body[b];
    for (std::uint32_t k : boundary_neighbours.of(b))
      if (particles.body[k] == own) sum += kernel.value(x[b] - x[k]);
    particles.boundary_volume[b] = Real(1) / sum;
  });
}

}  // namespace upf
