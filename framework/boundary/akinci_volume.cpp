#include "framework/boundary/akinci_volume.h"

namespace upf {

namespace {

// V_b for one boundary particle b.
struct BoundaryVolumeStage {
  const Vec3* x;
  const ParticleType* type;
  const BodyId* body;
  const Real* known;  // null when the scene knows no volumes
  NeighbourView neighbours;
  CubicSplineKernel kernel;
  TypeMask boundary;
  Real* volume;

  UPF_HD void operator()(std::uint32_t b) const {
    if (!in_mask(boundary, type[b])) return;
    if (known && known[b] > 0) {
      volume[b] = known[b];
      return;
    }
    Real sum = kernel.value(Real(0));
    // A body's particles see only their own body, so a body's sampling, and its volumes, stay the
    // same as it moves past walls and other bodies; walls (no body) see walls.
    const BodyId own = body[b];
    for (std::uint32_t k = neighbours.offsets[b]; k < neighbours.offsets[b + 1]; ++k) {
      const std::uint32_t j = neighbours.indices[k];
      if (body[j] == own) sum += kernel.value(x[b] - x[j]);
    }
    volume[b] = Real(1) / sum;
  }
};

}  // namespace

void compute_boundary_volumes(Particles& particles, TypeMask boundary,
                              const NeighbourList& boundary_neighbours,
                              const CubicSplineKernel& kernel, const CpuExecutor& exec) {
  const std::vector<Real>* known = particles.find_scalar(kKnownBoundaryVolumeField);
  exec.run(all_particles(particles.size()),
           BoundaryVolumeStage{particles.position.data(), particles.type.data(),
                               particles.body.data(), known ? known->data() : nullptr,
                               view_of(boundary_neighbours), kernel, boundary,
                               particles.boundary_volume.data()});
}

}  // namespace upf
