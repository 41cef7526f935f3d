#include "coupling/bodies/bodies_section.h"

#include <sstream>

#include "coupling/bodies/fluid_carving.h"
#include "coupling/bodies/rigid_body_system.h"
#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mass_properties.h"
#include "coupling/mesh/mesh_loader.h"
#include "coupling/mesh/mesh_source_json.h"
#include "coupling/motion/prescribed_motion_json.h"
#include "coupling/sampling/surface_sampler.h"
#include "framework/scene/json_input.h"
#include "framework/world/world.h"

namespace upf {

namespace {

using nlohmann::json;

struct BodiesData : SceneSectionData {
  std::vector<BodySource> bodies;
  std::vector<std::optional<PrescribedMotion>> motions;
  double estimated_particles() const override {
    double n = 0;
    for (const auto& b : bodies) n += double(b.samples.size());
    return n;
  }
};

// Loads, checks, measures and samples the mesh; every failure becomes a problem under `path`.
bool load_body_mesh(const MeshSource& source, const std::string& path, double spacing,
                    std::optional<double> density, BodySource& body, JsonInput& in) {
  try {
    body.mesh = load_mesh(source.file, source.transform, path);
    orient_outward(body.mesh);
    if (density) body.mass = mass_properties(body.mesh, *density, path);
    SurfaceSamplingOptions options;
    options.spacing = spacing;
    const SurfaceSamples samples = sample_surface(body.mesh, options, path);
    // Two layers, half a spacing and one and a half spacings inside the surface, as the layers
    // of a container wall sit outside its box: fluid then rests with its particle centres half a
    // spacing from the mesh, so its volume reaches the surface and a floating body displaces
    // the volume of its mesh. Layers on the surface itself made bodies float high: fluid rests
    // about one spacing from the samples, a skin of empty space that adds buoyancy. One layer
    // alone lets fast impacts push fluid through (a sheet's gradient vanishes on the sheet).
    body.samples.clear();
    body.normals.clear();
    for (double depth : {0.5, 1.5})
      for (std::size_t k = 0; k < samples.positions.size(); ++k) {
        body.samples.push_back(samples.positions[k] - depth * spacing * samples.normals[k]);
        body.normals.push_back(depth == 0.5 ? samples.normals[k] : Eigen::Vector3d::Zero());
      }
  } catch (const InputError& e) {
    for (const auto& p : e.problems()) in.problem(p.where.empty() ? path : p.where, p.message);
    return false;
  }
  return true;
}

std::optional<BodySource> read_body(const json& node, const std::string& path, std::size_t index,
                                    const SceneDescription& scene, JsonInput& in,
                                    std::optional<PrescribedMotion>& motion) {
  in.check_keys(node, path, {"name", "material", "mesh", "velocity", "angular_velocity", "motion"});
  BodySource body;
  body.name = in.string(node, path, "name", false).value_or("body" + std::to_string(index));
  const auto material = in.string(node, path, "material", true);
  if (!material) return std::nullopt;
  const Material* mat = nullptr;
  std::vector<std::string> names;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    names.push_back(scene.materials[m].name);
    if (scene.materials[m].name != *material) continue;
    mat = &scene.materials[m];
    body.material_id = MaterialId(m);
  }
  const std::string material_path = JsonInput::child(path, "material");
  if (!mat) {
    if (scene.rejected(*material)) return std::nullopt;  // reported at its definition
    std::string msg = "unknown material '" + *material + "'";
    if (auto guess = did_you_mean(*material, names)) msg += " (did you mean '" + *guess + "'?)";
    in.problem(material_path, msg);
    return std::nullopt;
  }
  if (mat->type != ParticleType::Rigid && mat->type != ParticleType::Frozen) {
    in.problem(material_path, "material '" + *material + "' is " +
                                  std::string(to_string(mat->type)) +
                                  "; a body needs a rigid material (moved by Bullet) or a frozen "
                                  "one (a static or kinematic obstacle)");
    return std::nullopt;
  }
  body.material = *material;
  body.friction = mat->param("friction");
  body.restitution = mat->param("restitution");
  const bool dynamic = mat->type == ParticleType::Rigid;
  body.kind = dynamic ? BodyKind::Dynamic : BodyKind::Static;

  for (const char* key : {"velocity", "angular_velocity"}) {
    if (!node.contains(key)) continue;
    if (!dynamic) {
      in.problem(JsonInput::child(path, key),
                 "only a rigid body has an initial velocity; a frozen body moves by 'motion'");
      continue;
    }
    if (auto v = in.vec3(node, path, key, true))
      (std::string(key) == "velocity" ? body.velocity : body.angular_velocity) = *v;
  }
  std::optional<Eigen::Vector3d> pivot;
  if (auto it = node.find("motion"); it != node.end()) {
    const std::string motion_path = JsonInput::child(path, "motion");
    if (dynamic) {
      in.problem(motion_path,
                 "a rigid body moves under forces; prescribed motion needs a frozen material");
    } else {
      motion = read_prescribed_motion(*it, motion_path, in);
      pivot = read_pivot(*it, motion_path, in);
      if (motion && motion->moves()) body.kind = BodyKind::Kinematic;
    }
  }

  if (!node.contains("mesh")) {
    in.problem(JsonInput::child(path, "mesh"), "missing: every body needs a mesh");
    return std::nullopt;
  }
  const std::string mesh_path = JsonInput::child(path, "mesh");
  const auto source = read_mesh_source(node["mesh"], mesh_path,
                                       std::filesystem::path(scene.source).parent_path(), in);
  if (!source) return std::nullopt;
  std::optional<double> density;  // assigned, not a ?: of optionals (GCC 12 -Wmaybe-uninitialized)
  if (dynamic) density = mat->param("density");
  if (!load_body_mesh(*source, mesh_path, double(scene.world.spacing), density, body, in))
    return std::nullopt;
  body.pivot = pivot.value_or(bounding_box(body.mesh).center());

  // A rigid body outside every container would fall for ever.
  if (dynamic && !scene.containers.empty()) {
    const Eigen::AlignedBox3d box = bounding_box(body.mesh);
    bool inside = false;
    for (const auto& c : scene.containers)
      inside = inside || c.box.contains(Box{box.min(), box.max()}, 1e-9);
    if (!inside) {
      std::ostringstream msg;
      msg << "the body's mesh spans [" << box.min().transpose() << "] - [" << box.max().transpose()
          << "], which is not inside any container";
      in.problem(mesh_path, msg.str());
      return std::nullopt;
    }
  }
  return body;
}

std::shared_ptr<const SceneSectionData> read_bodies(const json& node, const std::string& path,
                                                    const SceneDescription& scene, JsonInput& in) {
  if (!node.is_array()) {
    in.problem(path, "expected an array of bodies, found " + json_type_name(node));
    return nullptr;
  }
  auto data = std::make_shared<BodiesData>();
  bool ok = true;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string body_path = JsonInput::child(path, i);
    if (!in.expect_object(node[i], body_path)) {
      ok = false;
      continue;
    }
    std::optional<PrescribedMotion> motion;
    auto body = read_body(node[i], body_path, i, scene, in, motion);
    if (!body) {
      ok = false;
      continue;
    }
    for (const auto& other : data->bodies)
      if (other.name == body->name)
        in.problem(JsonInput::child(body_path, "name"), "duplicate body name '" + body->name + "'");
    data->bodies.push_back(std::move(*body));
    data->motions.push_back(std::move(motion));
  }
  if (!ok) return nullptr;
  return data;
}

// The six wall slabs of a container, as thick as its particle layers.
void add_container_slabs(const ContainerDesc& c, double spacing, const Material& material,
                         std::vector<StaticWall>& walls) {
  const double t = c.layers * spacing;
  const Eigen::Vector3d center = 0.5 * (c.box.min + c.box.max);
  const Eigen::Vector3d half = 0.5 * (c.box.max - c.box.min);
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {-1, 1}) {
      StaticWall w;
      w.center = center;
      w.center[axis] += side * (half[axis] + 0.5 * t);
      w.half_extents = half + Eigen::Vector3d::Constant(t);
      w.half_extents[axis] = 0.5 * t;
      w.friction = material.param("friction");
      w.restitution = material.param("restitution");
      walls.push_back(w);
    }
}

void build_bodies(World& world, const SceneDescription& scene, const SceneSectionData& section) {
  const auto& data = static_cast<const BodiesData&>(section);
  std::vector<RigidBodySystem::Body> bodies;
  for (const auto& b : data.bodies) carve_fluid(world.particles(), b, double(scene.world.spacing));
  for (std::size_t i = 0; i < data.bodies.size(); ++i) {
    RigidBodySystem::Body b;
    b.source = data.bodies[i];
    b.motion = data.motions[i];
    bodies.push_back(std::move(b));
  }
  std::vector<StaticWall> walls;
  for (const auto& c : scene.containers)
    for (const auto& m : scene.materials)
      if (m.name == c.material) add_container_slabs(c, double(scene.world.spacing), m, walls);
  const Vec3 g = scene.world.gravity;
  auto system = std::make_unique<RigidBodySystem>(std::move(bodies), std::move(walls),
                                                  double(scene.world.spacing),
                                                  Eigen::Vector3d(g.x, g.y, g.z));
  system->add_particles(world.particles());
  world.add_body_system(std::move(system));
}

}  // namespace

SceneSection bodies_scene_section() {
  return {"bodies",
          "rigid bodies (rigid material, moved by Bullet) and mesh obstacles (frozen material, "
          "static or with a prescribed motion)",
          read_bodies, build_bodies};
}

void register_coupling(Registry& registry) {
  registry.add_scene_section(bodies_scene_section());
}

}  // namespace upf
