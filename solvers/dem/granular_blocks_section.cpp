#include "solvers/dem/granular_blocks_section.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "framework/core/errors.h"

#include "framework/core/vec3_eigen.h"
#include "framework/scene/json_input.h"
#include "framework/scene/scene.h"
#include "framework/world/world.h"

namespace upf {

namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// Random sequential addition jams near a solid fraction of 0.38 for equal spheres (Widom 1966;
// Talbot et al. 1991); below 0.3 it places every grain in a few tries.
constexpr double kMaxRandomFraction = 0.3;

struct GranularBlock {
  MaterialId material = 0;
  Box box;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double radius = 0;
  std::array<long long, 3> count{};  // lattice: grains per axis
  bool random = false;               // random sequential packing instead of the lattice
  double solid_fraction = 0;         // random: grain volume / block volume
  std::uint64_t seed = 1;            // random: the generator's seed
  long long random_count = 0;        // random: grains to place
  std::string path;                  // for an error while placing
};

struct GranularBlocksData : SceneSectionData {
  std::vector<GranularBlock> blocks;
  double estimated_particles() const override {
    double n = 0;
    for (const auto& b : blocks)
      n += b.random ? double(b.random_count)
                    : double(b.count[0]) * double(b.count[1]) * double(b.count[2]);
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
    in.check_keys(b, where,
                  {"material", "min", "max", "velocity", "packing", "solid_fraction", "seed"});
    GranularBlock block;
    block.path = where;
    const std::string packing = in.string(b, where, "packing", false).value_or("lattice");
    if (packing != "lattice" && packing != "random")
      in.problem(JsonInput::child(where, "packing"),
                 "unknown packing '" + packing + "' (allowed: 'lattice', 'random')");
    block.random = packing == "random";
    if (!block.random && (b.contains("solid_fraction") || b.contains("seed")))
      in.problem(where, "solid_fraction and seed belong to \"packing\": \"random\"");
    block.solid_fraction = in.number(b, where, "solid_fraction", 0.25, 0, kMaxRandomFraction, true);
    block.seed = std::uint64_t(in.number(b, where, "seed", 1, 0, 4294967295.0));
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
        std::ostringstream message;  // %g-like, never a 300-digit number
        message << "the block is thinner than one grain diameter (" << pitch << " m)";
        in.problem(JsonInput::child(where, "max"), message.str());
        ok = false;
      }
    }
    if (block.random) {
      const Eigen::Vector3d size = *hi - *lo;
      const double grain_volume = 4.0 / 3.0 * kPi * block.radius * block.radius * block.radius;
      const double grains =
          std::floor(block.solid_fraction * std::max(0.0, size.prod()) / grain_volume);
      block.random_count = (long long)std::min(grains, 1e15);
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

// A uniform double in [0, 1) from the generator's top 53 bits: std::mt19937_64's sequence is
// fixed by the standard, the distributions of <random> are not, so this is the same everywhere.
double uniform(std::mt19937_64& rng) {
  return double(rng() >> 11) * 0x1.0p-53;
}

// Random sequential addition (Widom 1966): grain centres drawn uniformly in the block (a radius
// inside its faces), each kept only if it overlaps no grain kept before. A grid of cells one
// diameter wide finds the grains that could overlap. Deterministic for a seed.
std::vector<Eigen::Vector3d> random_sequential_packing(const GranularBlock& b) {
  const double r = b.radius, d = 2 * r;
  const Eigen::Vector3d lo = b.box.min + Eigen::Vector3d::Constant(r);
  const Eigen::Vector3d extent = (b.box.max - b.box.min - Eigen::Vector3d::Constant(d)).cwiseMax(0);
  std::array<long long, 3> cells{};
  for (int a = 0; a < 3; ++a)
    cells[std::size_t(a)] = std::max(1LL, (long long)std::ceil(extent[a] / d));
  std::vector<std::vector<std::uint32_t>> grid(std::size_t(cells[0] * cells[1] * cells[2]));
  auto cell_of = [&](const Eigen::Vector3d& x, int a) {
    return std::clamp((long long)std::floor((x[a] - lo[a]) / d), 0LL, cells[std::size_t(a)] - 1);
  };
  std::vector<Eigen::Vector3d> placed;
  placed.reserve(std::size_t(b.random_count));
  std::mt19937_64 rng(b.seed);
  const long long max_tries = 1000 * b.random_count + 1000;
  for (long long tries = 0; (long long)placed.size() < b.random_count; ++tries) {
    if (tries >= max_tries)
      throw InputError(JsonInput::child(b.path, "solid_fraction"),
                       "random packing placed " + std::to_string(placed.size()) + " of " +
                           std::to_string(b.random_count) +
                           " grains; the block is too small for this fraction (lower it)");
    Eigen::Vector3d x;
    for (int a = 0; a < 3; ++a) x[a] = lo[a] + uniform(rng) * extent[a];
    const long long ci = cell_of(x, 0), cj = cell_of(x, 1), ck = cell_of(x, 2);
    bool free = true;
    for (long long k = std::max(0LL, ck - 1); free && k <= std::min(cells[2] - 1, ck + 1); ++k)
      for (long long j = std::max(0LL, cj - 1); free && j <= std::min(cells[1] - 1, cj + 1); ++j)
        for (long long i = std::max(0LL, ci - 1); free && i <= std::min(cells[0] - 1, ci + 1); ++i)
          for (std::uint32_t other : grid[std::size_t((k * cells[1] + j) * cells[0] + i)])
            if ((placed[other] - x).squaredNorm() < d * d) {
              free = false;
              break;
            }
    if (!free) continue;
    grid[std::size_t((ck * cells[1] + cj) * cells[0] + ci)].push_back(std::uint32_t(placed.size()));
    placed.push_back(x);
  }
  return placed;
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
    if (b.random) {
      for (const Eigen::Vector3d& x : random_sequential_packing(b))
        p.add(to_vec3(x), v, mass, ParticleType::Granular, b.material);
      continue;
    }
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
          "boxes filled with grains of a granular material (touching, on a cubic lattice, or at "
          "random at a given solid fraction)",
          read_blocks, build_blocks};
}

}  // namespace upf
