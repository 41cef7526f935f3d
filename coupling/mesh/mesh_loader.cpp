#include "coupling/mesh/mesh_loader.h"

#include "coupling/mesh/declared_counts.h"
#include "coupling/mesh/isolated_read.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <bit>
#include <cstdint>
#include <limits>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "coupling/mesh/mesh_error.h"
#include "coupling/mesh/mesh_validation.h"

namespace upf {

namespace {

// Exact positions as bit patterns: vertices are joined only where they are identical.
struct PositionKey {
  std::uint64_t x, y, z;
  bool operator==(const PositionKey&) const = default;
};
struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ k.y) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ k.z) * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

// Joins vertices at identical positions, keeping the first occurrence's order (deterministic).
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh& mesh) : mesh_(mesh) {}
  std::uint32_t index_of(const Eigen::Vector3d& p) {
    // + 0.0 turns -0.0 into +0.0, so the two zeros join.
    const PositionKey key{std::bit_cast<std::uint64_t>(p.x() + 0.0),
                          std::bit_cast<std::uint64_t>(p.y() + 0.0),
                          std::bit_cast<std::uint64_t>(p.z() + 0.0)};
    auto [it, inserted] =
        index_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> index_;
};

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return out;
}

// Appends the triangles of one mesh instance, placed by the node's accumulated transform.
void append_mesh(const aiMesh& source, const Eigen::Matrix4d& placement, VertexWelder& welder,
                 TriangleMesh& out, const std::string& where) {
  // A mirroring node transform turns the surface inside out: reverse to keep the winding.
  const bool mirrored = placement.topLeftCorner<3, 3>().determinant() < 0;
  if ((source.mNumVertices && !source.mVertices) || (source.mNumFaces && !source.mFaces))
    throw mesh_error(out.source, where, "assimp returned a mesh without its arrays");
  std::vector<std::uint32_t> joined(source.mNumVertices);
  for (unsigned i = 0; i < source.mNumVertices; ++i) {
    const aiVector3D& v = source.mVertices[i];
    const Eigen::Vector4d p = placement * Eigen::Vector4d(v.x, v.y, v.z, 1.0);
    joined[i] = welder.index_of(p.head<3>());
  }
  for (unsigned f = 0; f < source.mNumFaces; ++f) {
    const aiFace& face = source.mFaces[f];
    if (face.mNumIndices != 3 || !face.mIndices) continue;  // points and lines: no surface
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      if (face.mIndices[k] >= source.mNumVertices)
        throw mesh_error(out.source, where, "a face refers to a vertex that does not exist");
      t[std::size_t(k)] = joined[face.mIndices[k]];
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // collapsed to an edge or point
    if (mirrored) std::swap(t[1], t[2]);
    out.triangles.push_back(t);
  }
}

// Every mesh of every node, depth first from the root (a fixed order: deterministic output).
TriangleMesh merge_scene(const aiScene& scene, std::string source, const std::string& where) {
  TriangleMesh out;
  out.source = std::move(source);
  VertexWelder welder(out);
  std::vector<std::pair<const aiNode*, Eigen::Matrix4d>> pending{
      {scene.mRootNode, Eigen::Matrix4d::Identity()}};
  std::unordered_set<const aiNode*> visited;  // a tree: a node seen twice is a broken file
  while (!pending.empty()) {
    const auto [node, parent] = pending.back();
    pending.pop_back();
    if (!visited.insert(node).second)
      throw mesh_error(out.source, where, "its node hierarchy has a cycle");
    const Eigen::Matrix4d placement = parent * to_eigen(node->mTransformation);
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      if (!node->mMeshes || node->mMeshes[i] >= scene.mNumMeshes ||
          !scene.mMeshes[node->mMeshes[i]])
        throw mesh_error(out.source, where, "a node refers to a mesh that does not exist");
      const aiMesh& mesh = *scene.mMeshes[node->mMeshes[i]];
      if (out.vertices.size() + mesh.mNumVertices > std::numeric_limits<std::uint32_t>::max())
        throw mesh_error(out.source, where, "has more than 2^32 vertices");
      append_mesh(mesh, placement, welder, out, where);
    }
    // Pushed in reverse so that children are visited in their stored order.
    for (unsigned c = node->mNumChildren; c-- > 0;)
      if (node->mChildren && node->mChildren[c])
        pending.emplace_back(node->mChildren[c], placement);
  }
  return out;
}

void require_readable_file(const std::filesystem::path& file, const std::string& where) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw mesh_error(file.string(), where, "does not exist");
  if (!std::filesystem::is_regular_file(status))
    throw mesh_error(file.string(), where, "is not a regular file");
  if (std::filesystem::file_size(file, error) == 0 && !error)
    throw mesh_error(file.string(), where, "is empty (0 bytes)");
}

void require_supported_format(const Assimp::Importer& importer, const std::filesystem::path& file,
                              const std::string& where) {
  const std::string extension = file.extension().string();
  if (!extension.empty() && importer.IsExtensionSupported(extension)) return;
  throw mesh_error(file.string(), where,
                   "unsupported mesh format '" + extension +
                       "': use .obj, .stl, .ply, .gltf or .glb (assimp also reads .fbx, .dae, "
                       ".3ds, .off and others)");
}

const aiScene* read_with_assimp(Assimp::Importer& importer, const std::filesystem::path& file,
                                const std::string& where) {
  // Only positions matter: dropping normals, texture coordinates and colours before
  // JoinIdenticalVertices lets it join the corners that those attributes kept apart.
  importer.SetPropertyInteger(
      AI_CONFIG_PP_RVC_FLAGS,
      aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
          aiComponent_TEXCOORDS | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
          aiComponent_TEXTURES | aiComponent_LIGHTS | aiComponent_CAMERAS | aiComponent_MATERIALS);
  // No aiProcess_ValidateDataStructure: it rejects a file without faces with a message about
  // "Mesh  contains no faces"; merge_scene checks every count and index itself and says "no
  // triangles". Points and lines are skipped there too.
  const unsigned steps =
      aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
  const aiScene* scene = importer.ReadFile(file.string(), steps);
  if (!scene)
    throw mesh_error(file.string(), where,
                     std::string("assimp could not read it: ") + importer.GetErrorString());
  return scene;
}

void apply_transform(TriangleMesh& mesh, const MeshTransform& transform) {
  for (auto& v : mesh.vertices) v = transform.apply(v);
  if (transform.mirrors()) flip_winding(mesh);
}

}  // namespace

TriangleMesh load_mesh(const std::filesystem::path& file, const MeshTransform& transform,
                       const std::string& where) {
  require_valid_transform(transform, where.empty() ? file.string() : where);
  require_readable_file(file, where);
  require_supported_format(Assimp::Importer(), file, where);
  // Before assimp allocates for counts the file cannot hold (declared_counts.h).
  require_counts_fit(file, where);
  // assimp in a child process: it aborts on some malformed files (isolated_read.h).
  TriangleMesh mesh = read_isolated(
      [&] {
        Assimp::Importer importer;
        const aiScene* scene = read_with_assimp(importer, file, where);
        TriangleMesh merged;
        if (scene->mRootNode && !(scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
          merged = merge_scene(*scene, file.string(), where);
        return merged;
      },
      file.string(), where);
  mesh.source = file.string();
  require_usable_surface(mesh, where);  // before the transform: a NaN in the file shows as such
  apply_transform(mesh, transform);
  require_usable_surface(mesh, where);  // after: an extreme scale can overflow
  return mesh;
}

}  // namespace upf
