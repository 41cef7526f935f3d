// PLY and OBJ mesh files (framework/output/mesh_ply_obj_writer.h), read back by a minimal reader
// written here from the format descriptions: PLY, Greg Turk, "The PLY Polygon File Format"
// (binary_little_endian, element vertex with float x y z, element face with a uchar-counted int
// list); OBJ, Wavefront's "v" and 1-based "f" lines.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/output/mesh_ply_obj_writer.h"
#include "test_output_support.h"

namespace upf {
namespace {

using output_test::output_error_message;
using output_test::read_all;
using output_test::TempDirTest;

namespace fs = std::filesystem;
using MeshPlyObjWriterTest = TempDirTest;

MeshPiece tetrahedron() {
  MeshPiece m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.25}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return m;
}

// Little-endian 4-byte values (this test runs on little-endian machines).
template <class T>
T get4(const std::string& s, std::size_t at) {
  static_assert(sizeof(T) == 4);
  T v;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

TEST_F(MeshPlyObjWriterTest, PlyIsBinaryLittleEndianWithFloatVerticesAndIntFaces) {
  const MeshPiece m = tetrahedron();
  write_mesh_ply(dir_ / "t.ply", m);
  const std::string text = read_all(dir_ / "t.ply");
  const std::string end = "end_header\n";
  const std::size_t body = text.find(end);
  ASSERT_NE(body, std::string::npos);
  const std::string header = text.substr(0, body + end.size());
  EXPECT_EQ(header,
            "ply\nformat binary_little_endian 1.0\ncomment upf liquid surface\n"
            "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 4\nproperty list uchar int vertex_indices\nend_header\n");
  std::size_t at = header.size();
  ASSERT_EQ(text.size(), at + 4 * 12 + 4 * 13);
  for (const auto& v : m.vertices)
    for (int k = 0; k < 3; ++k, at += 4) EXPECT_EQ(get4<float>(text, at), float(v[k]));
  for (const auto& t : m.triangles) {
    EXPECT_EQ(static_cast<unsigned char>(text[at]), 3u);
    ++at;
    for (int k = 0; k < 3; ++k, at += 4) EXPECT_EQ(get4<std::int32_t>(text, at), int(t[k]));
  }
}

TEST_F(MeshPlyObjWriterTest, ObjHasOneBasedFacesInTheSameWinding) {
  write_mesh_obj(dir_ / "t.obj", tetrahedron());
  std::istringstream in(read_all(dir_ / "t.obj"));
  std::string line;
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<int, 3>> f;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::string tag;
    l >> tag;
    if (tag == "v") {
      std::array<double, 3> p{};
      l >> p[0] >> p[1] >> p[2];
      v.push_back(p);
    } else if (tag == "f") {
      std::array<int, 3> t{};
      l >> t[0] >> t[1] >> t[2];
      f.push_back(t);
    } else {
      EXPECT_EQ(tag, "#") << line;
    }
  }
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[3][2], 0.25);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0], (std::array<int, 3>{1, 3, 2}));
  EXPECT_EQ(f[3], (std::array<int, 3>{1, 4, 3}));
}

TEST_F(MeshPlyObjWriterTest, EmptyMeshGivesValidEmptyFiles) {
  write_mesh_ply(dir_ / "e.ply", MeshPiece{});
  const std::string ply = read_all(dir_ / "e.ply");
  EXPECT_NE(ply.find("element vertex 0\n"), std::string::npos);
  EXPECT_NE(ply.find("element face 0\n"), std::string::npos);
  EXPECT_EQ(ply.substr(ply.size() - 11), "end_header\n");
  write_mesh_obj(dir_ / "e.obj", MeshPiece{});
  EXPECT_EQ(read_all(dir_ / "e.obj"), "# upf liquid surface: 0 vertices, 0 triangles\n");
}

TEST_F(MeshPlyObjWriterTest, BadIndexThrowsAndWritesNothing) {
  MeshPiece m = tetrahedron();
  m.triangles[2][1] = 4;
  EXPECT_THROW(write_mesh_ply(dir_ / "b.ply", m), std::invalid_argument);
  EXPECT_THROW(write_mesh_obj(dir_ / "b.obj", m), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir_ / "b.ply"));
  EXPECT_FALSE(fs::exists(dir_ / "b.obj"));
}

TEST_F(MeshPlyObjWriterTest, MissingDirectoryThrowsOutputErrorNamingPath) {
  const fs::path file = dir_ / "no_such_dir" / "s.ply";
  const std::string msg = output_error_message([&] { write_mesh_ply(file, tetrahedron()); });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
}

}  // namespace
}  // namespace upf
