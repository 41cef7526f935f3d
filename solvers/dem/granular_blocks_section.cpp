#include "solvers/dem/granular_blocks_section.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/core/vec3_eigen.h"
#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/world/world.h"

namespace upf {

namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

struct GranularBlock {
  MaterialId material = 0;
  Box box;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double radius = 0;
  std::array<long long, 3> count{};
};

struct GranularBlocksData : SceneSectionData {
  std::vector<GranularBlock> blocks;
  double estimated_particles() const override {
    double n = 0;
    for (const auto& b : blocks) n += double(b.count[0]) * double(b.count[1]) * double(b.count[2]);
    return n;
  }
};

std::shared_ptr<const SceneSectionData> read_blocks(const json& node, const std::string& path,
                                                    const SceneDescription& scene, JsonInput& in) {
  if (!node.is_array()) {
    in.problem(path, "expected an array of granular blocks, found " + json_type_name(node));
    return nullptr;
  }
  auto data = std::make_shared<GranularBlocksData>();
  bool ok = true;
  const double spacing = double(scene.world.spacing);
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string where = JsonInput::child(path, i);
    if (!in.expect_object(node[i], where)) {
      ok = false;
      continue;
    }
    const json& b = node[i];
    in.check_keys(b, where, {"material", "min", "max", "velocity"});
    GranularBlock block;
    const auto name = in.string(b, where, "material", true);
    const Material* mat = nullptr;
    for (std::size_t m = 0; name && m < scene.materials.size(); ++m)
      if (scene.materials[m].name == *name) {
        mat = &scene.materials[m];
        block.material = MaterialId(m);
      }
    const std::string material_path = JsonInput::child(where, "material");
    if (name && !mat) in.problem(material_path, "unknown material '" + *name + "'");
    if (mat && mat->type != ParticleType::Granular)
      in.problem(material_path, "material '" + *name + "' is " + std::string(to_string(mat->type)) +
                                    "; a granular block needs a granular material");
    if (!mat || mat->type != ParticleType::Granular) {
      ok = false;
      continue;
    }
    block.radius = mat->param("radius") > 0 ? mat->param("radius") : 0.5 * spacing;
    if (block.radius > spacing) {
      std::ostringstream msg;
      msg << "grain radius " << block.radius << " m is larger than the particle spacing ("
          << spacing << " m): neighbour search reaches 2 spacings, contacts must stay inside";
      in.problem(JsonInput::child("/materials/" + *name, "radius"), msg.str());
      ok = false;
      continue;
    }
    auto lo = in.vec3(b, where, "min", true);
    auto hi = in.vec3(b, where, "max", true);
    if (auto v = in.vec3(b, where, "velocity", false)) block.velocity = *v;
    if (!lo || !hi) {
      ok = false;
      continue;
    }
    block.box = Box{*lo, *hi};
    const double pitch = 2 * block.radius;
    for (int a = 0; a < 3; ++a) {
      // Counted in double first: an inverted or astronomically large block must not overflow
      // the integer (found by tests/fuzz/fuzz_scene.cpp); the memory estimate rejects big ones.
      const double grains = std::floor(((*hi)[a] - (*lo)[a]) / pitch + 1e-9);
      block.count[std::size_t(a)] = grains >= 1 ? (long long)std::min(grains, 1e15) : 0;
      if (block.count[std::size_t(a)] < 1) {
        in.problem(
            JsonInput::child(where, "max"),
            "the block is thinner than one grain diameter (" + std::to_string(pitch) + " m)");
        ok = false;
      }
    }
    bool inside = false;
    for (const auto& c : scene.containers) inside = inside || c.box.contains(block.box, 1e-9);
    if (!inside) {
      in.problem(where, "granular block is not inside any container");
      ok = false;
    }
    data->blocks.push_back(block);
  }
  if (!ok) return nullptr;
  return data;
}

void build_blocks(World& world, const SceneDescription& scene, const SceneSectionData& section) {
  (void)scene;
  const auto& data = static_cast<const GranularBlocksData&>(section);
  Particles& p = world.particles();
  for (const auto& b : data.blocks) {
    const double r = b.radius;
    const Real mass =
        Real(world.materials()[b.material].param("density") * 4.0 / 3.0 * kPi * r * r * r);
    const Vec3 v = to_vec3(b.velocity);
    for (long long k = 0; k < b.count[2]; ++k)
      for (long long j = 0; j < b.count[1]; ++j)
        for (long long i = 0; i < b.count[0]; ++i) {
          const Eigen::Vector3d x =
              b.box.min +
              (2 * r) * Eigen::Vector3d(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
          p.add(to_vec3(x), v, mass, ParticleType::Granular, b.material);
        }
  }
}

}  // namespace

SceneSection granular_blocks_scene_section() {
  return {"granular_blocks",
          "boxes filled with grains of a granular material (touching, on a cubic lattice)",
          read_blocks, build_blocks};
}

}  // namespace upf
