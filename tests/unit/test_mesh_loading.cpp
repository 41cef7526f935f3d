// Mesh loading through assimp: every shipped asset in every shipped format (OBJ, binary PLY,
// GLB, binary STL, text glTF), the placement convention x = position + R (scale .* (unit x))
// checked on bounding boxes and a tracked corner, glTF node transforms and merging, and every
// kind of bad file giving an InputError that names the file. The expected counts and extents
// are those scripts/make_assets.py writes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mass_properties.h"
#include "coupling/mesh/mesh_loader.h"
#include "coupling/mesh/mesh_source_json.h"
#include "test_mesh_support.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
using mesh_test::asset;
using mesh_test::input_error_text;
using mesh_test::test_mesh;

void expect_box(const TriangleMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                double tolerance) {
  const Eigen::AlignedBox3d box = bounding_box(mesh);
  EXPECT_LE((box.min() - lo).cwiseAbs().maxCoeff(), tolerance)
      << "min " << box.min().transpose() << " expected " << lo.transpose();
  EXPECT_LE((box.max() - hi).cwiseAbs().maxCoeff(), tolerance)
      << "max " << box.max().transpose() << " expected " << hi.transpose();
}

TEST(MeshLoading, ObjBoxQuadsAreTriangulatedAndCornersJoined) {
  const TriangleMesh mesh = load_mesh(asset("unit_box.obj"));
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);  // 6 quads
  expect_box(mesh, Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5), 0);
  EXPECT_DOUBLE_EQ(surface_area(mesh), 6.0);
  EXPECT_TRUE(is_closed(mesh));
  EXPECT_GT(signed_volume(mesh), 0);  // counter-clockwise seen from outside
  EXPECT_EQ(mesh.source, asset("unit_box.obj").string());
}

TEST(MeshLoading, PlyIcosphereHasAllVerticesOnTheSphere) {
  const TriangleMesh mesh = load_mesh(asset("icosphere.ply"));
  EXPECT_EQ(mesh.vertices.size(), 2562u);  // icosahedron subdivided 4 times
  EXPECT_EQ(mesh.triangles.size(), 5120u);
  for (const auto& v : mesh.vertices) EXPECT_NEAR(v.norm(), 0.5, 1e-7);  // float storage
  EXPECT_TRUE(is_closed(mesh));
  EXPECT_GT(signed_volume(mesh), 0);
}

TEST(MeshLoading, GlbTorusIsNonConvexAndClosed) {
  const TriangleMesh mesh = load_mesh(asset("torus.glb"));
  EXPECT_EQ(mesh.vertices.size(), 96u * 48u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 96u * 48u);
  expect_box(mesh, {-0.5, -0.5, -0.15}, {0.5, 0.5, 0.15}, 1e-7);
  EXPECT_TRUE(is_closed(mesh));
  EXPECT_GT(signed_volume(mesh), 0);
}

TEST(MeshLoading, StlInMillimetresIsScaledByItsUnit) {
  // Binary STL repeats every corner per triangle: joining identical positions gives 12.
  MeshTransform in_mm;
  in_mm.unit = *length_unit_in_metres("mm");
  const TriangleMesh mesh = load_mesh(asset("l_block_mm.stl"), in_mm);
  EXPECT_EQ(mesh.vertices.size(), 12u);
  EXPECT_EQ(mesh.triangles.size(), 20u);
  expect_box(mesh, {0, 0, 0}, {0.04, 0.04, 0.02}, 1e-15);
  EXPECT_TRUE(is_closed(mesh));
  const TriangleMesh raw = load_mesh(asset("l_block_mm.stl"));
  expect_box(raw, {0, 0, 0}, {40, 40, 20}, 0);
}

TEST(MeshLoading, GltfNodeTransformsAreAppliedAndMeshesMerged) {
  // Parent at z = 5; one box at x = -1, one at x = +1 mirrored in x and stretched 2x in y.
  const TriangleMesh mesh = load_mesh(test_mesh("two_boxes.gltf"));
  EXPECT_EQ(mesh.vertices.size(), 16u);
  EXPECT_EQ(mesh.triangles.size(), 24u);
  expect_box(mesh, {-1.5, -1, 4.5}, {1.5, 1, 5.5}, 1e-12);
  // The mirrored instance was rewound: still closed and outward, volume 1 + 2.
  EXPECT_TRUE(is_closed(mesh));
  EXPECT_NEAR(signed_volume(mesh), 3.0, 1e-12);
}

TEST(MeshLoading, TransformScalesRotatesThenTranslates) {
  MeshTransform transform;
  transform.scale = {2, 3, 4};
  transform.rotation = rotation_from_axis_angle_degrees({0, 0, 1}, 90);  // (x, y) -> (-y, x)
  transform.position = {10, 20, 30};
  const TriangleMesh mesh = load_mesh(asset("unit_box.obj"), transform);
  // Scaled: [-1, 1] x [-1.5, 1.5] x [-2, 2]; rotated: x in [-1.5, 1.5], y in [-1, 1].
  expect_box(mesh, {8.5, 19, 28}, {11.5, 21, 32}, 1e-12);
  // The file's corner (0.5, 0.5, 0.5) -> scaled (1, 1.5, 2) -> rotated (-1.5, 1, 2) -> moved.
  const Eigen::Vector3d corner(8.5, 21, 32);
  double nearest = INFINITY;
  for (const auto& v : mesh.vertices) nearest = std::min(nearest, (v - corner).norm());
  EXPECT_LT(nearest, 1e-12);
  EXPECT_NEAR(signed_volume(mesh), 24.0, 1e-9);
}

TEST(MeshLoading, MirroringScaleKeepsNormalsOutward) {
  MeshTransform mirror;
  mirror.scale = {-1, 1, 1};
  const TriangleMesh mesh = load_mesh(asset("torus.glb"), mirror);
  EXPECT_TRUE(is_closed(mesh));
  EXPECT_GT(signed_volume(mesh), 0);
}

TEST(MeshLoading, LengthUnits) {
  EXPECT_EQ(length_unit_in_metres("m"), 1.0);
  EXPECT_EQ(length_unit_in_metres("mm"), 0.001);
  EXPECT_EQ(length_unit_in_metres("cm"), 0.01);
  EXPECT_EQ(length_unit_in_metres("in"), 0.0254);
  EXPECT_FALSE(length_unit_in_metres("furlong"));
  EXPECT_EQ(length_unit_names(), "m, cm, mm, um, km, in, ft");
}

class MeshLoadingErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("upf_mesh_errors_" + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  // The error's text names the file, the JSON path, and says `what`.
  static void expect_error(const fs::path& file, const std::string& what,
                           const MeshTransform& transform = {}) {
    const std::string text =
        input_error_text([&] { load_mesh(file, transform, "/bodies/0/mesh"); });
    EXPECT_NE(text.find(file.string()), std::string::npos) << text;
    EXPECT_NE(text.find("/bodies/0/mesh"), std::string::npos) << text;
    EXPECT_NE(text.find(what), std::string::npos) << text;
  }
  fs::path dir_;
};

TEST_F(MeshLoadingErrors, MissingFile) {
  expect_error(test_mesh("no_such_mesh.obj"), "does not exist");
}

TEST_F(MeshLoadingErrors, DirectoryIsNotAMesh) {
  expect_error(dir_, "is not a regular file");
}

TEST_F(MeshLoadingErrors, ZeroByteFile) {
  expect_error(write("nothing.stl", ""), "is empty");
}

TEST_F(MeshLoadingErrors, UnsupportedFormat) {
  expect_error(test_mesh("not_a_mesh.txt"), "unsupported mesh format '.txt'");
}

TEST_F(MeshLoadingErrors, GarbageQuotesAssimp) {
  expect_error(test_mesh("garbage.stl"), "assimp could not read it");
}

// Found by tests/fuzz/fuzz_mesh.cpp: a face index list with garbage bytes makes assimp's
// triangulation abort() (an ai_assert). The reader runs in a child process, so this is an error
// naming the file, not a dead program.
TEST_F(MeshLoadingErrors, FileThatAbortsAssimpIsAnError) {
  expect_error(test_mesh("assimp_abort.off"), "crashed on it (signal 6");
}

// Also found by fuzz_mesh: an OFF file on which assimp's reader segfaults.
TEST_F(MeshLoadingErrors, FileThatCrashesAssimpIsAnError) {
  expect_error(test_mesh("assimp_segv.off"), "crashed on it (signal 11");
}

// Found by fuzz_mesh on 2026-12-05: a 308-byte PLY with a mangled header on which assimp's reader
// never finishes. The reader is stopped after its time limit (5 s for a small file) and the
// file is named.
TEST_F(MeshLoadingErrors, FileThatAssimpNeverFinishesIsAnError) {
  expect_error(test_mesh("assimp_loop.ply"), "did not finish within 5 s");
}

TEST_F(MeshLoadingErrors, NoFacesIsEmpty) {
  expect_error(test_mesh("empty.obj"), "contains no triangles");
}

TEST_F(MeshLoadingErrors, OnlyLinesIsEmpty) {
  expect_error(write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n"),
               "contains no triangles");
}

TEST_F(MeshLoadingErrors, CollinearTrianglesAreDegenerate) {
  expect_error(test_mesh("flat.obj"), "triangles have zero area");
}

TEST_F(MeshLoadingErrors, NonFiniteVertex) {
  expect_error(write("huge.obj", "v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n"), "is not finite");
}

TEST_F(MeshLoadingErrors, ScaleThatOverflows) {
  MeshTransform huge;
  huge.scale = Eigen::Vector3d::Constant(1e308);
  huge.unit = 1e10;
  expect_error(asset("unit_box.obj"), "is not finite", huge);
}

TEST_F(MeshLoadingErrors, ZeroScale) {
  MeshTransform flat;
  flat.scale = {1, 0, 1};
  const std::string text = input_error_text([&] { load_mesh(asset("unit_box.obj"), flat); });
  EXPECT_NE(text.find("scale factor"), std::string::npos) << text;
  EXPECT_NE(text.find("unit_box.obj"), std::string::npos) << text;
}

TEST(MeshSource, ReadsEveryKey) {
  const auto node = nlohmann::json::parse(R"({
    "file": "meshes/part.stl", "units": "mm", "scale": [1, 2, -1],
    "rotation": {"axis": [0, 0, 2], "degrees": 90}, "position": [1, 2, 3]})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  const auto source = read_mesh_source(node, "/bodies/0/mesh", "/scenes", input);
  ASSERT_TRUE(source) << problems.front().where << ": " << problems.front().message;
  EXPECT_EQ(source->file, fs::path("/scenes/meshes/part.stl"));
  EXPECT_EQ(source->transform.unit, 0.001);
  EXPECT_EQ(source->transform.scale, Eigen::Vector3d(1, 2, -1));
  EXPECT_TRUE(source->transform.rotation.toRotationMatrix().isApprox(
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-15));
  EXPECT_EQ(source->transform.position, Eigen::Vector3d(1, 2, 3));
}

TEST(MeshSource, DefaultsAndOneNumberScale) {
  const auto node = nlohmann::json::parse(R"({"file": "/abs/box.obj", "scale": 2})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  const auto source = read_mesh_source(node, "/m", "/scenes", input);
  ASSERT_TRUE(source);
  EXPECT_EQ(source->file, fs::path("/abs/box.obj"));
  EXPECT_EQ(source->transform.unit, 1.0);
  EXPECT_EQ(source->transform.scale, Eigen::Vector3d::Constant(2));
  EXPECT_TRUE(
      source->transform.rotation.coeffs().isApprox(Eigen::Quaterniond::Identity().coeffs()));
  EXPECT_EQ(source->transform.position, Eigen::Vector3d::Zero());
}

TEST(MeshSource, ReportsEveryProblemWithItsPath) {
  const auto node = nlohmann::json::parse(R"({
    "units": "furlong", "scale": [1, 0, 1], "rotation": {"axis": [0, 0, 0], "degrees": 5},
    "positon": [0, 0, 0]})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  EXPECT_FALSE(read_mesh_source(node, "/m", ".", input));
  std::string all;
  for (const auto& p : problems) all += p.where + ": " + p.message + "\n";
  EXPECT_NE(all.find("/m/file: missing"), std::string::npos) << all;
  EXPECT_NE(all.find("/m/units: unknown length unit 'furlong' (use m, cm, mm"), std::string::npos)
      << all;
  EXPECT_NE(all.find("/m/scale: scale factors must be finite and non-zero"), std::string::npos)
      << all;
  EXPECT_NE(all.find("/m/rotation/axis: the rotation axis must not be zero"), std::string::npos)
      << all;
  EXPECT_NE(all.find("/m/positon: unknown key 'positon' (did you mean 'position'?)"),
            std::string::npos)
      << all;
}

}  // namespace
}  // namespace upf
