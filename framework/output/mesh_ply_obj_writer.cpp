// PLY and OBJ mesh writers; formats in mesh_ply_obj_writer.h.
#include "framework/output/mesh_ply_obj_writer.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/output/atomic_file.h"

namespace upf {

namespace {

void check_mesh(const MeshPiece& mesh, const char* writer) {
  if (mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument(std::string(writer) + ": too many vertices for 32-bit indices");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t])
      if (v >= mesh.vertices.size())
        throw std::invalid_argument(std::string(writer) + ": triangle " + std::to_string(t) +
                                    " uses vertex " + std::to_string(v) + " of " +
                                    std::to_string(mesh.vertices.size()));
}

// Appends the little-endian bytes of `value` (float or int32) to `out`.
template <class T>
void put_le(std::vector<char>& out, T value) {
  static_assert(sizeof(T) == 4);
  std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
  char bytes[4];
  std::memcpy(bytes, &bits, 4);
  out.insert(out.end(), bytes, bytes + 4);
}

}  // namespace

void write_mesh_ply(const std::filesystem::path& path, const MeshPiece& mesh) {
  check_mesh(mesh, "write_mesh_ply");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment upf liquid surface\n"
      "element vertex " +
      std::to_string(mesh.vertices.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\n"
      "element face " +
      std::to_string(mesh.triangles.size()) +
      "\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<char> body;
  body.reserve(12 * mesh.vertices.size() + 13 * mesh.triangles.size());
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) put_le(body, static_cast<float>(v[k]));
  for (const auto& t : mesh.triangles) {
    body.push_back(char(3));
    for (std::uint32_t v : t) put_le(body, static_cast<std::int32_t>(v));
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(header.data(), std::streamsize(header.size()));
    out.write(body.data(), std::streamsize(body.size()));
  });
}

void write_mesh_obj(const std::filesystem::path& path, const MeshPiece& mesh) {
  check_mesh(mesh, "write_mesh_obj");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# upf liquid surface: " << mesh.vertices.size() << " vertices, "
        << mesh.triangles.size() << " triangles\n";
    char line[128];
    for (const auto& v : mesh.vertices) {
      // 9 significant digits: a float survives the round trip.
      const int n = std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", v.x(), v.y(), v.z());
      out.write(line, n);
    }
    for (const auto& t : mesh.triangles) {
      const int n = std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
      out.write(line, n);
    }
  });
}

}  // namespace upf
