#include "framework/scene/scene_builder.h"

#include <map>

#include "framework/boundary/akinci_volume.h"
#include "framework/core/vec3_eigen.h"

namespace upf {

void add_container_walls(Particles& particles, const Box& box, Real spacing, int layers,
                         MaterialId material, const std::array<bool, 3>& open) {
  // The lattice is stretched slightly per axis so that the walls sit exactly on the box faces.
  const Lattice n = wall_lattice_size(box, spacing);
  Eigen::Vector3d step;
  for (int a = 0; a < 3; ++a) step[a] = (box.max[a] - box.min[a]) / double(n[a]);
  // Along an open (periodic) axis the walls stop at the box: their images continue them.
  std::int64_t from[3], to[3];
  for (int a = 0; a < 3; ++a) {
    from[a] = open[std::size_t(a)] ? 0 : -layers;
    to[a] = open[std::size_t(a)] ? n[a] : n[a] + layers;
  }
  for (std::int64_t k = from[2]; k < to[2]; ++k)
    for (std::int64_t j = from[1]; j < to[1]; ++j)
      for (std::int64_t i = from[0]; i < to[0]; ++i) {
        const bool inside = i >= 0 && i < n[0] && j >= 0 && j < n[1] && k >= 0 && k < n[2];
        if (inside) continue;
        const Eigen::Vector3d x =
            box.min +
            Eigen::Vector3d(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5).cwiseProduct(step);
        particles.add(to_vec3(x), Vec3{}, Real(0), ParticleType::Frozen, material);
      }
}

void add_fluid_block(Particles& particles, const Box& box, Real spacing, const Vec3& velocity,
                     Real particle_mass, MaterialId material, bool ball) {
  const Lattice n = fluid_lattice_size(box, spacing);
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max);
  const Eigen::Vector3d radii = 0.5 * (box.max - box.min);
  for (std::int64_t k = 0; k < n[2]; ++k)
    for (std::int64_t j = 0; j < n[1]; ++j)
      for (std::int64_t i = 0; i < n[0]; ++i) {
        const Eigen::Vector3d x =
            box.min +
            Eigen::Vector3d(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5) * double(spacing);
        if (ball && (x - centre).cwiseQuotient(radii).squaredNorm() > 1) continue;
        particles.add(to_vec3(x), velocity, particle_mass, ParticleType::Liquid, material);
      }
}

std::unique_ptr<World> build_world(const SceneDescription& scene, const Registry& registry,
                                   int threads) {
  auto world = std::make_unique<World>(scene.world, threads);
  for (const auto& m : scene.materials) world->materials().add(m);
  const Real h = scene.world.spacing;

  Particles& p = world->particles();
  p.reserve(std::size_t(scene.estimated_particles()));
  for (const auto& c : scene.containers) {
    const std::size_t first = p.size();
    add_container_walls(p, c.box, h, c.layers, *world->materials().find(c.material),
                        {scene.world.periodic.periodic[0], scene.world.periodic.periodic[1],
                         scene.world.periodic.periodic[2]});
    world->add_container(
        {to_vec3(c.box.min), to_vec3(c.box.max), *world->materials().find(c.material)});
    // Lattice walls have a known volume per particle: the (slightly stretched) lattice cell.
    auto& known = p.scalar_field(kKnownBoundaryVolumeField, Real(0));
    const Lattice n = wall_lattice_size(c.box, h);
    double cell = 1;
    for (int a = 0; a < 3; ++a) cell *= (c.box.max[a] - c.box.min[a]) / double(n[a]);
    for (std::size_t i = first; i < p.size(); ++i) known[i] = Real(cell);
  }
  for (const auto& b : scene.fluid_blocks) {
    const MaterialId id = *world->materials().find(b.material);
    // m = rho0 h^3: on the initial lattice the SPH density sum then gives rho0.
    const Real mass = Real(world->materials()[id].param("density")) * h * h * h;
    add_fluid_block(p, b.box, h, to_vec3(b.velocity), mass, id, b.ball);
  }

  for (const auto& section : scene.sections)
    registry.find_scene_section(section.key)->build(*world, scene, *section.data);

  // One solver instance per name, moving every material that names it.
  std::map<std::string, std::vector<MaterialId>> by_solver;
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (!scene.materials[i].solver.empty())
      by_solver[scene.materials[i].solver].push_back(MaterialId(i));
  // In name order; World::prepare orders them by what they declare to write and read (the
  // grains' drag comes back to the liquid in the same step: granular before fluid solvers).
  for (auto& [name, materials] : by_solver) {
    const SolverInfo* info = registry.find_solver(name);
    const ParamValues& params = scene.materials[materials.front()].solver_params;
    world->add_solver(info->create(params, materials), info->coupling);
  }
  return world;
}

}  // namespace upf
