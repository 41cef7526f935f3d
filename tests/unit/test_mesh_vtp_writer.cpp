// Tests for write_mesh_vtp, the rigid-body mesh frame writer: pieces concatenated into one VTK XML
// PolyData file with triangles as Polys and per-piece cell data. The file is parsed back
// independently of the writer (test_output_support.h), following the VTK XML file format
// documentation: https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/errors.h"
#include "framework/output/mesh_vtp_writer.h"
#include "tests/unit/test_output_support.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
using output_test::ArrayInfo;
using output_test::output_error_message;
using output_test::parse_vtp;
using output_test::read_all;
using output_test::TempDirTest;
using output_test::unclosed_elements;
using output_test::VtpFile;
using output_test::write_text;

class MeshVtpWriterTest : public TempDirTest {};

using Fields = std::vector<std::pair<std::string, std::vector<double>>>;

// A tetrahedron with its right-angle corner at `corner`, triangles wound outwards.
MeshPiece tetrahedron(const Eigen::Vector3d& corner) {
  MeshPiece m;
  m.name = "tet";
  m.vertices = {corner, corner + Eigen::Vector3d(1, 0, 0), corner + Eigen::Vector3d(0, 1, 0),
                corner + Eigen::Vector3d(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// An axis-aligned cube of edge `edge` from `low`, two triangles per face, wound outwards.
MeshPiece cube(const Eigen::Vector3d& low, double edge) {
  MeshPiece m;
  m.name = "cube";
  for (int i = 0; i < 8; ++i) {  // vertex i has bit 0 -> x, bit 1 -> y, bit 2 -> z at the top
    m.vertices.push_back(low + edge * Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  }
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},   // z = low, z = high
                 {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},   // y = low, y = high
                 {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};  // x = low, x = high
  return m;
}

std::vector<double> flatten(const std::vector<MeshPiece>& pieces) {
  std::vector<double> out;
  for (const MeshPiece& p : pieces) {
    for (const Eigen::Vector3d& x : p.vertices) out.insert(out.end(), {x.x(), x.y(), x.z()});
  }
  return out;
}

// The name of the <Piece> child element (CellData, Points, Polys, ...) that holds array `name`.
std::string section_of(const VtpFile& f, const std::string& name) {
  const std::size_t at = f.xml.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return "";
  const std::size_t open = f.xml.rfind("\n      <", at);
  const std::size_t begin = open + 8;
  return f.xml.substr(begin, f.xml.find('>', begin) - begin);
}

TEST_F(MeshVtpWriterTest, WritesPiecesAsTrianglesWithCellData) {
  const std::vector<MeshPiece> pieces = {tetrahedron({0.5, -1.25, 2}), cube({3, 0.1, -7}, 0.25)};
  const fs::path file = dir_ / "bodies_000001.vtp";
  write_mesh_vtp(file, pieces, {{"speed", {1.5, 2.25}}, {"mass", {1e-7, 4e3}}});
  EXPECT_FALSE(fs::exists(dir_ / "bodies_000001.vtp.tmp"));

  const VtpFile f = parse_vtp(file);
  EXPECT_EQ(f.piece.at("NumberOfPoints"), "12");
  EXPECT_EQ(f.piece.at("NumberOfPolys"), "16");
  EXPECT_EQ(f.piece.at("NumberOfVerts"), "0");
  EXPECT_EQ(f.piece.at("NumberOfLines"), "0");
  EXPECT_EQ(f.piece.at("NumberOfStrips"), "0");

  std::vector<std::string> names;
  for (const ArrayInfo& a : f.arrays) names.push_back(a.name);
  EXPECT_EQ(names, (std::vector<std::string>{"body", "speed", "mass", "Points", "connectivity",
                                             "offsets"}));
  for (const char* name : {"body", "speed", "mass"}) EXPECT_EQ(section_of(f, name), "CellData");
  EXPECT_EQ(section_of(f, "Points"), "Points");
  EXPECT_EQ(section_of(f, "connectivity"), "Polys");
  EXPECT_EQ(section_of(f, "offsets"), "Polys");
  EXPECT_EQ(f.find("body")->type, "Int32");
  EXPECT_EQ(f.find("speed")->type, "Float64");
  EXPECT_EQ(f.find("speed")->components, 1);
  EXPECT_EQ(f.find("Points")->type, "Float64");
  EXPECT_EQ(f.find("Points")->components, 3);
  EXPECT_EQ(f.find("connectivity")->type, "Int64");
  EXPECT_EQ(f.find("offsets")->type, "Int64");

  EXPECT_EQ(f.decode<double>("Points"), flatten(pieces));
  // The cube's indices follow the tetrahedron's 4 points.
  std::vector<std::int64_t> connectivity;
  for (const auto& t : pieces[0].triangles)
    connectivity.insert(connectivity.end(), t.begin(), t.end());
  for (const auto& t : pieces[1].triangles) {
    for (const std::uint32_t v : t) connectivity.push_back(4 + v);
  }
  EXPECT_EQ(f.decode<std::int64_t>("connectivity"), connectivity);
  std::vector<std::int64_t> offsets;
  for (std::int64_t end = 3; end <= 48; end += 3) offsets.push_back(end);
  EXPECT_EQ(f.decode<std::int64_t>("offsets"), offsets);

  std::vector<std::int32_t> body(4, 0);
  body.resize(16, 1);
  EXPECT_EQ(f.decode<std::int32_t>("body"), body);
  std::vector<double> speed(4, 1.5);
  speed.resize(16, 2.25);
  EXPECT_EQ(f.decode<double>("speed"), speed);
  std::vector<double> mass(4, 1e-7);
  mass.resize(16, 4e3);
  EXPECT_EQ(f.decode<double>("mass"), mass);

  // The blocks are contiguous, the last one ends where the XML resumes, and the elements nest.
  const ArrayInfo& last = f.arrays.back();
  const std::size_t end = last.offset + sizeof(std::uint64_t) + 16 * sizeof(std::int64_t);
  EXPECT_EQ(f.raw.substr(end), "\n  </AppendedData>\n</VTKFile>\n");
  EXPECT_EQ(unclosed_elements(f.xml + "<AppendedData encoding=\"raw\">"),
            (std::vector<std::string>{"VTKFile", "AppendedData"}));
}

TEST_F(MeshVtpWriterTest, BodyIsTheIndexInPiecesEvenPastAnEmptyPiece) {
  MeshPiece nothing;
  nothing.name = "empty";
  const fs::path file = dir_ / "bodies.vtp";
  write_mesh_vtp(file, {tetrahedron({0, 0, 0}), nothing, tetrahedron({5, 0, 0})},
                 {{"speed", {1, 2, 3}}});
  const VtpFile f = parse_vtp(file);
  EXPECT_EQ(f.piece.at("NumberOfPoints"), "8");
  EXPECT_EQ(f.piece.at("NumberOfPolys"), "8");
  EXPECT_EQ(f.decode<std::int32_t>("body"), (std::vector<std::int32_t>{0, 0, 0, 0, 2, 2, 2, 2}));
  EXPECT_EQ(f.decode<double>("speed"), (std::vector<double>{1, 1, 1, 1, 3, 3, 3, 3}));
  EXPECT_EQ(f.decode<std::int64_t>("connectivity").back(), 7);
}

TEST_F(MeshVtpWriterTest, NoPiecesGiveAValidEmptyFile) {
  const fs::path file = dir_ / "none.vtp";
  write_mesh_vtp(file, {}, {{"speed", {}}});
  const VtpFile f = parse_vtp(file);
  EXPECT_EQ(f.piece.at("NumberOfPoints"), "0");
  EXPECT_EQ(f.piece.at("NumberOfPolys"), "0");
  ASSERT_EQ(f.arrays.size(), 5u);
  for (const ArrayInfo& a : f.arrays) EXPECT_TRUE(f.decode<char>(a.name).empty()) << a.name;
  EXPECT_EQ(f.raw.substr(5 * sizeof(std::uint64_t)), "\n  </AppendedData>\n</VTKFile>\n");
  EXPECT_EQ(unclosed_elements(f.xml + "<AppendedData encoding=\"raw\">"),
            (std::vector<std::string>{"VTKFile", "AppendedData"}));
}

TEST_F(MeshVtpWriterTest, BadInputThrowsInvalidArgumentAndWritesNothing) {
  const fs::path file = dir_ / "bodies.vtp";
  write_text(file, "old");
  MeshPiece broken = cube({0, 0, 0}, 1);
  broken.triangles[5][1] = 8;  // one past the last vertex
  try {
    write_mesh_vtp(file, {tetrahedron({0, 0, 0}), broken}, {});
    ADD_FAILURE() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'cube'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("vertex 8"), std::string::npos) << msg;
  }
  const std::vector<MeshPiece> two = {tetrahedron({0, 0, 0}), cube({2, 0, 0}, 1)};
  EXPECT_THROW(write_mesh_vtp(file, two, {{"speed", {1.0}}}), std::invalid_argument);
  EXPECT_THROW(write_mesh_vtp(file, two, {{"speed", {1, 2, 3}}}), std::invalid_argument);
  EXPECT_THROW(write_mesh_vtp(file, two, {{"body", {1, 2}}}), std::invalid_argument);
  EXPECT_THROW(write_mesh_vtp(file, two, {{"speed", {1, 2}}, {"speed", {3, 4}}}),
               std::invalid_argument);
  EXPECT_EQ(read_all(file), "old");
  EXPECT_FALSE(fs::exists(dir_ / "bodies.vtp.tmp"));
}

TEST_F(MeshVtpWriterTest, MissingDirectoryThrowsOutputErrorNamingPath) {
  const fs::path file = dir_ / "no_such_dir" / "bodies.vtp";
  const std::string msg = output_error_message([&] {
    write_mesh_vtp(file, {tetrahedron({0, 0, 0})}, {});
  });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
}

}  // namespace
}  // namespace upf
