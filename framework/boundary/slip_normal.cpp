#include "framework/boundary/slip_normal.h"

#include "framework/world/body_particle_stages.h"

namespace upf {

namespace {

struct SlipNormalStage {
  const Vec3* x;      // world positions
  const Vec3* local;  // body-frame positions, or null
  const ParticleType* type;
  const BodyId* body;
  const MaterialId* material;
  const std::uint8_t* free_slip;  // per material
  std::size_t materials;
  NeighbourView neighbours;
  CubicSplineKernel kernel;
  Vec3* world_normal;
  Vec3* body_normal;  // null without body particles

  void operator()(std::uint32_t b) const {
    if (!in_mask(kBoundaryMask, type[b])) return;
    if (material[b] >= materials || free_slip[material[b]] == 0) return;
    const BodyId own = body[b];
    const bool in_body = own != kNoBody && local != nullptr;
    const Vec3* pos = in_body ? local : x;
    Vec3 g{};
    Real scale = 0;
    for (std::uint32_t k = neighbours.offsets[b]; k < neighbours.offsets[b + 1]; ++k) {
      const std::uint32_t j = neighbours.indices[k];
      if (body[j] != own) continue;
      const Vec3 r = pos[b] - pos[j];
      const Real w = kernel.value(r);
      g += r * w;
      scale += norm(r) * w;
    }
    const Real length = norm(g);
    const Vec3 n = length > Real(0.05) * scale && length > 0 ? g / length : Vec3{};
    if (in_body)
      body_normal[b] = n;
    else
      world_normal[b] = n;
  }
};

}  // namespace

std::vector<std::uint8_t> free_slip_materials(const MaterialTable& materials) {
  std::vector<std::uint8_t> free_slip(materials.size(), 0);
  const Material* slippery = nullptr;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const Material& material = materials[MaterialId(m)];
    if (!in_mask(kBoundaryMask, material.type) || !material.params.has("free_slip")) continue;
    free_slip[m] = material.param("free_slip") > 0 ? 1 : 0;
    if (free_slip[m] && !slippery) slippery = &material;
  }
  if (!slippery) return free_slip;
  for (const Material& liquid : materials.all()) {
    if (liquid.type != ParticleType::Liquid || !liquid.params.has("implicit_viscosity")) continue;
    if (liquid.param("implicit_viscosity") > 0 && liquid.param("boundary_viscosity") > 0)
      throw InputError("/materials/" + slippery->name + "/free_slip",
                       "free-slip walls need explicit viscosity, but liquid \"" + liquid.name +
                           "\" has implicit_viscosity 1 and a boundary_viscosity: set one of "
                           "them to 0 (docs/viscosity.md)");
  }
  return free_slip;
}

void compute_slip_normals(Particles& particles, const std::vector<std::uint8_t>& free_slip,
                          const NeighbourList& boundary_neighbours, const CubicSplineKernel& kernel,
                          const CpuExecutor& exec) {
  const std::vector<Vec3>* local = particles.find_vector(kBodyLocalPositionField);
  std::vector<Vec3>& world = particles.vector_field(kSlipNormalField);
  std::vector<Vec3>* in_body = local ? &particles.vector_field(kBodySlipNormalField) : nullptr;
  exec.run(all_particles(particles.size()),
           SlipNormalStage{particles.position.data(), local ? local->data() : nullptr,
                           particles.type.data(), particles.body.data(), particles.material.data(),
                           free_slip.data(), free_slip.size(), view_of(boundary_neighbours), kernel,
                           world.data(), in_body ? in_body->data() : nullptr});
}

}  // namespace upf
