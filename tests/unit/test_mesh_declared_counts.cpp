// Mesh headers that declare more vertices and faces than their files hold (issue 46, item 7): a
// 197-byte PLY claiming 10^7 of each took assimp 48 s and 1 GB before "no triangles". Now an
// InputError naming the file and the counts, before assimp runs; files that do hold their
// counts, to the last byte, still load.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "coupling/mesh/mesh_loader.h"
#include "test_mesh_support.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
using mesh_test::input_error_text;

class MeshDeclaredCounts : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("upf_declared_counts_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  fs::path dir_;
};

const char* kTetraVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const char* kTetraFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string ascii_ply(const std::string& vertices, const std::string& faces) {
  return "ply\nformat ascii 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

// The tetrahedron as binary little-endian PLY: 4 x 12 bytes of vertices, 4 x 13 of faces.
std::string binary_tetra_ply() {
  std::string out =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement face 4\n"
      "property list uchar int vertex_indices\nend_header\n";
  auto put = [&](const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& v : xyz)
    for (float c : v) put(c);
  const std::int32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    put(std::uint8_t(3));
    for (std::int32_t i : f) put(i);
  }
  return out;
}

TEST_F(MeshDeclaredCounts, AsciiPlyClaimingTenMillionElementsIsRefusedAtOnce) {
  // The file: a tetrahedron's worth of data under a header claiming 10^7 of each.
  const fs::path file =
      write("huge.ply", ascii_ply("10000000", "10000000") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string text = input_error_text([&] { load_mesh(file, {}, "/bodies/0/mesh"); });
  for (const std::string& needle :
       {std::string("/bodies/0/mesh"), file.string(),
        std::string("10000000 vertex and 10000000 face"), std::string("follow the header")})
    EXPECT_NE(text.find(needle), std::string::npos) << needle << "\n" << text;
}

TEST_F(MeshDeclaredCounts, AMangledHeaderWithAHugeCountIsRefusedToo) {
  // Found by fuzz_mesh: a PLY header too mangled to parse ("property list uc", an OFF line, binary
  // bytes) that still says "element vertex 10000000"; assimp believed it and ran past the
  // fuzzer's 20 s timeout. No element takes less than a byte of a 197-byte file.
  const fs::path file =
      fs::path(UPF_SOURCE_DIR) / "tests" / "data" / "meshes" / "mangled_header_huge_count.ply";
  const std::string text = input_error_text([&] { load_mesh(file, {}, "/bodies/0/mesh"); });
  EXPECT_NE(text.find("declares 10000000 elements, more than the file's"), std::string::npos)
      << text;
}

TEST_F(MeshDeclaredCounts, CountsBeyondEveryIntegerAreRefused) {
  const fs::path file = write("absurd.ply", ascii_ply("99999999999999999999999", "1") + "0 0 0\n");
  EXPECT_NE(input_error_text([&] { load_mesh(file); }).find("99999999999999999999999 vertex"),
            std::string::npos);
}

TEST_F(MeshDeclaredCounts, BinaryPlyMustHoldItsElementsToTheByte) {
  const std::string whole = binary_tetra_ply();
  EXPECT_EQ(load_mesh(write("tetra.ply", whole)).triangles.size(), 4u);
  const fs::path cut = write("cut.ply", whole.substr(0, whole.size() - 1));
  const std::string text = input_error_text([&] { load_mesh(cut); });
  EXPECT_NE(text.find("at least 100 bytes of data, but only 99 bytes"), std::string::npos) << text;
}

TEST_F(MeshDeclaredCounts, AsciiFilesThatHoldTheirCountsStillLoad) {
  // Without the last newline too: the last value needs no separator.
  std::string ply = ascii_ply("4", "4") + kTetraVertices + kTetraFaces;
  ply.pop_back();
  EXPECT_EQ(load_mesh(write("tetra.ply", ply)).triangles.size(), 4u);
  const std::string off = std::string("OFF 4 4 6\n# a comment\n") + kTetraVertices + kTetraFaces;
  EXPECT_EQ(load_mesh(write("tetra.off", off)).triangles.size(), 4u);
}

TEST_F(MeshDeclaredCounts, OffClaimingTenMillionElementsIsRefused) {
  const fs::path file = write("huge.off", "OFF\n# counts\n10000000 10000000 0\n0 0 0\n3 0 0 0\n");
  const std::string text = input_error_text([&] { load_mesh(file); });
  EXPECT_NE(text.find("10000000 vertex and 10000000 face"), std::string::npos) << text;
}

}  // namespace
}  // namespace upf
