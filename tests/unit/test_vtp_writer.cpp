// Tests for the output writers: atomic file replacement, the VTK XML PolyData (.vtp) frame writer
// and the ParaView .pvd series. The .vtp is parsed back here independently of the writer, following
// the VTK XML file format documentation:
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#include <gtest/gtest.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/core/errors.h"
#include "framework/output/atomic_file.h"
#include "framework/output/pvd_series.h"
#include "framework/output/vtp_writer.h"
#include "framework/particles/particles.h"
#include "tests/unit/test_output_support.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
using output_test::ArrayInfo;
using output_test::attributes;
using output_test::elements;
using output_test::output_error_message;
using output_test::parse_vtp;
using output_test::read_all;
using output_test::TempDirTest;
using output_test::unclosed_elements;
using output_test::VtpFile;
using output_test::write_text;

class AtomicFileTest : public TempDirTest {};
class VtpWriterTest : public TempDirTest {};
class PvdSeriesTest : public TempDirTest {};

constexpr const char* kRealName = std::is_same_v<Real, double> ? "Float64" : "Float32";

Particles sample_particles() {
  Particles p;
  p.add({0.5f, -1.25f, 2.0f}, {1, 2, 3}, 1, ParticleType::Liquid, 7);
  p.add({1e-3f, 4.0f, -0.0f}, {-1, 0.25f, 8}, 1, ParticleType::Granular, 2);
  p.add({3.0f, 3.5f, 1e6f}, {0, 0, -9.81f}, 2, ParticleType::Frozen, 65535, 4);
  auto& density = p.scalar_field("density", Real(1000), true);
  density = {Real(999.5), Real(1000.25), Real(1e-7)};
  auto& accel = p.vector_field("accel", Vec3{}, true);
  accel[1] = Vec3{Real(0.1), Real(0.2), Real(0.3)};
  p.scalar_field("unexported", Real(5));
  return p;
}

std::vector<Real> flatten(const std::vector<Vec3>& v) {
  std::vector<Real> out;
  for (const Vec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}

// ---------------------------------------------------------------------------------------------
// Atomic files

TEST_F(AtomicFileTest, ReplacesExistingFileAndLeavesNoTemp) {
  const fs::path p = dir_ / "a.txt";
  write_file_atomically(p, [](std::ostream& out) { out << "old"; });
  write_file_atomically(p, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(read_all(p), "new");
  EXPECT_FALSE(fs::exists(dir_ / "a.txt.tmp"));
}

TEST_F(AtomicFileTest, WriteErrorKeepsOldFileAndRemovesTemp) {
  const fs::path p = dir_ / "a.txt";
  write_text(p, "old");
  const std::string msg = output_error_message([&] {
    write_file_atomically(p, [](std::ostream& out) {
      out << "partial";
      out.setstate(std::ios::badbit);  // what a failed write(2) does to the stream
    });
  });
  EXPECT_NE(msg.find(p.string()), std::string::npos) << msg;
  EXPECT_EQ(read_all(p), "old");
  EXPECT_FALSE(fs::exists(dir_ / "a.txt.tmp"));
}

TEST_F(AtomicFileTest, DiskFullIsReportedWithReason) {
  // /dev/full fails every write with ENOSPC; reach it through the temporary file's name.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path p = dir_ / "frame.vtp";
  write_text(p, "old");
  fs::create_symlink("/dev/full", dir_ / "frame.vtp.tmp");
  const std::string msg = output_error_message([&] {
    write_file_atomically(p, [](std::ostream& out) { out << std::string(100000, 'x'); });
  });
  EXPECT_NE(msg.find(p.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find(std::strerror(ENOSPC)), std::string::npos) << msg;
  EXPECT_EQ(read_all(p), "old");
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir_ / "frame.vtp.tmp")));
  EXPECT_TRUE(fs::exists("/dev/full"));
}

TEST_F(AtomicFileTest, CallbackExceptionPropagatesAndRemovesTemp) {
  const fs::path p = dir_ / "a.txt";
  write_text(p, "old");
  EXPECT_THROW(write_file_atomically(p,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw std::runtime_error("boom");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_all(p), "old");
  EXPECT_FALSE(fs::exists(dir_ / "a.txt.tmp"));
}

TEST_F(AtomicFileTest, RenameFailureRemovesTempAndNamesPath) {
  const fs::path p = dir_ / "occupied";
  fs::create_directories(p / "inside");  // a non-empty directory cannot be replaced by a file
  const std::string msg = output_error_message(
      [&] { write_file_atomically(p, [](std::ostream& out) { out << "x"; }); });
  EXPECT_NE(msg.find(p.string()), std::string::npos) << msg;
  EXPECT_TRUE(fs::is_directory(p / "inside"));
  EXPECT_FALSE(fs::exists(dir_ / "occupied.tmp"));
}

TEST_F(AtomicFileTest, EnsureDirectoryCreatesNestedDirectories) {
  const fs::path d = dir_ / "a" / "b" / "c";
  ensure_directory(d);
  EXPECT_TRUE(fs::is_directory(d));
  ensure_directory(d);  // existing is fine
}

TEST_F(AtomicFileTest, EnsureDirectoryThrowsWhenAFileIsInTheWay) {
  write_text(dir_ / "file", "x");
  for (const fs::path& d : {dir_ / "file", dir_ / "file" / "sub"}) {
    const std::string msg = output_error_message([&] { ensure_directory(d); });
    EXPECT_NE(msg.find(d.string()), std::string::npos) << msg;
  }
}

// ---------------------------------------------------------------------------------------------
// .vtp frames

TEST_F(VtpWriterTest, RoundTripsArraysExactly) {
  const Particles p = sample_particles();
  const fs::path file = dir_ / "frame_000001.vtp";
  write_vtp(file, p, {"density", "no.such.field", "accel", "density"});
  EXPECT_FALSE(fs::exists(dir_ / "frame_000001.vtp.tmp"));

  const VtpFile f = parse_vtp(file);
  EXPECT_EQ(f.piece.at("NumberOfPoints"), "3");
  EXPECT_EQ(f.piece.at("NumberOfVerts"), "3");

  std::vector<std::string> names;
  for (const ArrayInfo& a : f.arrays) names.push_back(a.name);
  EXPECT_EQ(names, (std::vector<std::string>{"id", "type", "material", "velocity", "density",
                                             "accel", "Points", "connectivity", "offsets"}));
  EXPECT_EQ(f.find("id")->type, "UInt32");
  EXPECT_EQ(f.find("type")->type, "UInt8");
  EXPECT_EQ(f.find("material")->type, "UInt16");
  EXPECT_EQ(f.find("velocity")->type, kRealName);
  EXPECT_EQ(f.find("velocity")->components, 3);
  EXPECT_EQ(f.find("density")->type, kRealName);
  EXPECT_EQ(f.find("density")->components, 1);
  EXPECT_EQ(f.find("accel")->components, 3);
  EXPECT_EQ(f.find("Points")->type, kRealName);
  EXPECT_EQ(f.find("Points")->components, 3);
  EXPECT_EQ(f.find("connectivity")->type, "Int32");
  EXPECT_EQ(f.find("offsets")->type, "Int32");
  // The 'unexported' field was not asked for.
  EXPECT_EQ(f.find("unexported"), nullptr);

  EXPECT_EQ(f.decode<std::uint32_t>("id"), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(f.decode<std::uint8_t>("type"), (std::vector<std::uint8_t>{0, 2, 3}));
  EXPECT_EQ(f.decode<std::uint16_t>("material"), (std::vector<std::uint16_t>{7, 2, 65535}));
  EXPECT_EQ(f.decode<Real>("Points"), flatten(p.position));
  EXPECT_EQ(f.decode<Real>("velocity"), flatten(p.velocity));
  EXPECT_EQ(f.decode<Real>("density"), (std::vector<Real>{Real(999.5), Real(1000.25), Real(1e-7)}));
  EXPECT_EQ(f.decode<Real>("accel"), flatten(*p.find_vector("accel")));
  EXPECT_EQ(f.decode<std::int32_t>("connectivity"), (std::vector<std::int32_t>{0, 1, 2}));
  EXPECT_EQ(f.decode<std::int32_t>("offsets"), (std::vector<std::int32_t>{1, 2, 3}));

  // The blocks are contiguous and the last one ends where the XML resumes.
  const ArrayInfo& last = f.arrays.back();
  const std::size_t end = last.offset + sizeof(std::uint64_t) + 3 * sizeof(std::int32_t);
  EXPECT_EQ(f.raw.substr(end), "\n  </AppendedData>\n</VTKFile>\n");
  // Everything but the two elements closed in that tail is closed, in order, before the data.
  EXPECT_EQ(unclosed_elements(f.xml + "<AppendedData encoding=\"raw\">"),
            (std::vector<std::string>{"VTKFile", "AppendedData"}));
}

TEST_F(VtpWriterTest, IdsFollowParticlesAfterReordering) {
  Particles p = sample_particles();
  p.permute({2, 0, 1});
  const fs::path file = dir_ / "permuted.vtp";
  write_vtp(file, p, {"density"});
  const VtpFile f = parse_vtp(file);
  EXPECT_EQ(f.decode<std::uint32_t>("id"), (std::vector<std::uint32_t>{2, 0, 1}));
  EXPECT_EQ(f.decode<Real>("density"), (std::vector<Real>{Real(1e-7), Real(999.5), Real(1000.25)}));
  EXPECT_EQ(f.decode<Real>("Points"), flatten(p.position));
}

TEST_F(VtpWriterTest, EmptyParticlesGiveAValidEmptyFile) {
  const Particles p;
  const fs::path file = dir_ / "empty.vtp";
  write_vtp(file, p, {});
  const VtpFile f = parse_vtp(file);
  EXPECT_EQ(f.piece.at("NumberOfPoints"), "0");
  ASSERT_EQ(f.arrays.size(), 7u);
  EXPECT_TRUE(f.decode<Real>("Points").empty());
  EXPECT_TRUE(f.decode<std::int32_t>("offsets").empty());
}

// zlib-compressed frames hold the same values as raw ones, in VTK's vtkZLibDataCompressor
// layout (decoded by the test's own reader, test_output_support.h), in fewer bytes for arrays
// that repeat (types, materials, the vertex cells).
TEST_F(VtpWriterTest, CompressedFramesHoldTheSameArrays) {
  Particles p;
  for (int i = 0; i < 20000; ++i)
    p.add({Real(i % 37) * Real(0.01), Real(i % 101) * Real(0.02), Real(i) * Real(1e-4)},
          {Real(0.5), Real(i % 7), 0}, 1, ParticleType::Liquid, 3);
  const fs::path raw = dir_ / "raw.vtp", packed = dir_ / "packed.vtp";
  write_vtp(raw, p, {});
  write_vtp(packed, p, {}, vtk_xml::Compression::zlib);
  const VtpFile a = parse_vtp(raw), b = parse_vtp(packed);
  EXPECT_FALSE(a.compressed);
  ASSERT_TRUE(b.compressed);
  EXPECT_NE(b.xml.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  ASSERT_EQ(a.arrays.size(), b.arrays.size());
  for (const ArrayInfo& info : a.arrays)
    EXPECT_EQ(a.bytes_of(info.name), b.bytes_of(info.name)) << info.name;
  // 20000 particles: 80 kB of ids, over the 32 KiB block, so the blocks are walked.
  EXPECT_GT(a.bytes_of("id").size(), 2 * vtk_xml::kBlockBytes);
  EXPECT_LT(fs::file_size(packed), fs::file_size(raw) / 2);
}

TEST_F(VtpWriterTest, MissingDirectoryThrowsNamingPath) {
  const fs::path file = dir_ / "no_such_dir" / "frame.vtp";
  const std::string msg = output_error_message([&] { write_vtp(file, sample_particles(), {}); });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
}

TEST_F(VtpWriterTest, DirectoryThatIsAFileThrowsNamingPath) {
  write_text(dir_ / "plain_file", "x");
  const fs::path file = dir_ / "plain_file" / "frame.vtp";
  const std::string msg = output_error_message([&] { write_vtp(file, sample_particles(), {}); });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_EQ(read_all(dir_ / "plain_file"), "x");
}

TEST_F(VtpWriterTest, FailedRewriteLeavesPreviousFrameIntact) {
  const fs::path file = dir_ / "frame.vtp";
  write_vtp(file, sample_particles(), {"density"});
  const std::string before = read_all(file);
  // A directory where the temporary file should go makes the next write fail to open.
  fs::create_directory(dir_ / "frame.vtp.tmp");
  Particles other;
  other.add({9, 9, 9}, {}, 1, ParticleType::Liquid, 0);
  const std::string msg = output_error_message([&] { write_vtp(file, other, {}); });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_EQ(read_all(file), before);
  EXPECT_TRUE(fs::is_directory(dir_ / "frame.vtp.tmp"));  // not ours: left alone
}

// ---------------------------------------------------------------------------------------------
// .pvd series

TEST_F(PvdSeriesTest, ListsEveryAddedTimeAndFile) {
  const fs::path pvd = dir_ / "run.pvd";
  PvdSeries series(pvd);
  series.add(0.0, "frames/frame_000000.vtp");
  EXPECT_NE(read_all(pvd).find("frame_000000.vtp"), std::string::npos);  // on disk at once
  series.add(0.1, "frames/frame_000001.vtp");
  series.add(2.5e-3, "frames/a&b.vtp");

  const std::string xml = read_all(pvd);
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\""), std::string::npos);
  std::vector<std::pair<double, std::string>> entries;
  for (const std::string& element : elements(xml, "<DataSet")) {
    auto a = attributes(element);
    entries.emplace_back(std::stod(a["timestep"]), a["file"]);
  }
  const std::vector<std::pair<double, std::string>> expected = {
      {0.0, "frames/frame_000000.vtp"},
      {0.1, "frames/frame_000001.vtp"},
      {2.5e-3, "frames/a&amp;b.vtp"},
  };
  EXPECT_EQ(entries, expected);  // times round-trip exactly
  EXPECT_FALSE(fs::exists(dir_ / "run.pvd.tmp"));
}

TEST_F(PvdSeriesTest, UnwritableSeriesThrowsNamingPath) {
  const fs::path pvd = dir_ / "missing" / "run.pvd";
  PvdSeries series(pvd);
  const std::string msg = output_error_message([&] { series.add(0.0, "f.vtp"); });
  EXPECT_NE(msg.find(pvd.string()), std::string::npos) << msg;
}

TEST_F(PvdSeriesTest, SingleFileStepIsPartZeroInTheFixedLayout) {
  const fs::path pvd = dir_ / "run.pvd";
  PvdSeries series(pvd);
  series.add(0.25, "frames/frame_000000.vtp");
  EXPECT_EQ(read_all(pvd),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0.25\" group=\"\" part=\"0\" "
            "file=\"frames/frame_000000.vtp\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
}

struct DataSetEntry {
  double time;
  std::string part;
  std::string file;
  bool operator==(const DataSetEntry&) const = default;
};

std::vector<DataSetEntry> data_sets(const fs::path& pvd) {
  std::vector<DataSetEntry> entries;
  for (const std::string& element : elements(read_all(pvd), "<DataSet")) {
    auto a = attributes(element);
    entries.push_back({std::stod(a["timestep"]), a["part"], a["file"]});
  }
  return entries;
}

TEST_F(PvdSeriesTest, MultiFileStepsNumberTheirParts) {
  const fs::path pvd = dir_ / "run.pvd";
  PvdSeries series(pvd);
  series.add(0.0, {"frames/frame_000000.vtp", "frames/bodies_000000.vtp"});
  series.add(0.5, std::vector<std::string>{"frames/frame_000001.vtp", "frames/bodies_000001.vtp"});
  series.add(1.0, {"frames/frame_000002.vtp"});
  const std::vector<DataSetEntry> expected = {
      {0.0, "0", "frames/frame_000000.vtp"}, {0.0, "1", "frames/bodies_000000.vtp"},
      {0.5, "0", "frames/frame_000001.vtp"}, {0.5, "1", "frames/bodies_000001.vtp"},
      {1.0, "0", "frames/frame_000002.vtp"},
  };
  EXPECT_EQ(data_sets(pvd), expected);
  EXPECT_THROW(series.add(2.0, std::vector<std::string>{}), std::invalid_argument);
  EXPECT_EQ(data_sets(pvd), expected);
}

TEST_F(PvdSeriesTest, FailedMultiFileStepIsNotRecorded) {
  const fs::path pvd = dir_ / "later" / "run.pvd";
  PvdSeries series(pvd);
  output_error_message([&] { series.add(0.0, {"a_0.vtp", "b_0.vtp"}); });
  fs::create_directory(dir_ / "later");
  series.add(0.5, {"a_1.vtp", "b_1.vtp"});
  EXPECT_EQ(data_sets(pvd),
            (std::vector<DataSetEntry>{{0.5, "0", "a_1.vtp"}, {0.5, "1", "b_1.vtp"}}));
}

}  // namespace
}  // namespace upf
