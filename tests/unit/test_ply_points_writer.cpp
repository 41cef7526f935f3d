// Tests for the PLY point-cloud writer and the type palette. The file is parsed back here
// independently of the writer, following Paul Bourke's description of the PLY format
// (https://paulbourke.net/dataformats/ply/): ASCII header lines up to "end_header\n", then
// binary_little_endian records, one per vertex, properties packed in header order.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "framework/core/errors.h"
#include "framework/output/ply_points_writer.h"
#include "framework/output/type_palette.h"
#include "framework/particles/particles.h"
#include "tests/unit/test_output_support.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
using output_test::output_error_message;
using output_test::read_all;
using output_test::TempDirTest;
using output_test::write_text;

class PlyPointsWriterTest : public TempDirTest {};

struct PlyFile {
  std::vector<std::string> header;  // the lines, without their '\n', "ply" to "end_header"
  std::string body;                 // everything after "end_header\n"
};

PlyFile parse_ply(const fs::path& p) {
  const std::string text = read_all(p);
  PlyFile f;
  const std::string end = "end_header\n";
  const std::size_t at = text.find(end);
  EXPECT_NE(at, std::string::npos) << "no end_header in " << p;
  if (at == std::string::npos) return f;
  std::size_t line = 0;
  while (line < at + end.size()) {
    const std::size_t nl = text.find('\n', line);
    f.header.push_back(text.substr(line, nl - line));
    line = nl + 1;
  }
  f.body = text.substr(at + end.size());
  return f;
}

// Reads the little-endian value at `at` and moves past it (the tests run on little-endian hosts,
// as do all the platforms upf builds for).
template <class T>
T take(const std::string& body, std::size_t& at) {
  T value{};
  EXPECT_LE(at + sizeof(T), body.size());
  if (at + sizeof(T) <= body.size()) std::memcpy(&value, body.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

const std::vector<std::string> kFixedHeader = {
    "ply",
    "format binary_little_endian 1.0",
    "comment upf particles: one vertex per particle, coloured by type",
    "",  // element vertex N: filled in by header_for()
    "property float x",
    "property float y",
    "property float z",
    "property uint8 red",
    "property uint8 green",
    "property uint8 blue",
    "property uint32 id",
    "property uint8 type",
    "property uint16 material",
    "property float vx",
    "property float vy",
    "property float vz",
};

std::vector<std::string> header_for(std::size_t n, const std::vector<std::string>& extra) {
  std::vector<std::string> h = kFixedHeader;
  h[3] = "element vertex " + std::to_string(n);
  for (const auto& e : extra) h.push_back("property float " + e);
  h.push_back("end_header");
  return h;
}

Particles sample_particles() {
  Particles p;
  p.add({0.5f, -1.25f, 2.0f}, {1, 2, 3}, 1, ParticleType::Liquid, 7);
  p.add({1e-3f, 4.0f, -0.0f}, {-1, 0.25f, 8}, 1, ParticleType::Granular, 2);
  p.add({3.0f, 3.5f, 1e6f}, {0, 0, -9.81f}, 2, ParticleType::Frozen, 65535, 4);
  p.add({-7.0f, 0.125f, 1.0f}, {0.5f, 0, 0}, 2, ParticleType::Rigid, 1, 0);
  auto& density = p.scalar_field("density", Real(1000), true);
  density = {Real(999.5), Real(1000.25), Real(1e-7), Real(-3)};
  auto& accel = p.vector_field("accel", Vec3{}, true);
  accel[1] = Vec3{Real(0.1), Real(0.2), Real(0.3)};
  p.scalar_field("unexported", Real(5));
  return p;
}

// The record of particle i as the header describes it, field by field.
struct Record {
  float x, y, z;
  std::uint8_t r, g, b;
  std::uint32_t id;
  std::uint8_t type;
  std::uint16_t material;
  float vx, vy, vz;
};

Record take_record(const std::string& body, std::size_t& at) {
  Record r{};
  r.x = take<float>(body, at);
  r.y = take<float>(body, at);
  r.z = take<float>(body, at);
  r.r = take<std::uint8_t>(body, at);
  r.g = take<std::uint8_t>(body, at);
  r.b = take<std::uint8_t>(body, at);
  r.id = take<std::uint32_t>(body, at);
  r.type = take<std::uint8_t>(body, at);
  r.material = take<std::uint16_t>(body, at);
  r.vx = take<float>(body, at);
  r.vy = take<float>(body, at);
  r.vz = take<float>(body, at);
  return r;
}

void expect_fixed(const Record& r, const Particles& p, std::size_t i) {
  EXPECT_EQ(r.x, float(p.position[i].x)) << i;
  EXPECT_EQ(r.y, float(p.position[i].y)) << i;
  EXPECT_EQ(r.z, float(p.position[i].z)) << i;
  const Rgb8 c = type_colour(p.type[i]);
  EXPECT_EQ(r.r, c.r) << i;
  EXPECT_EQ(r.g, c.g) << i;
  EXPECT_EQ(r.b, c.b) << i;
  EXPECT_EQ(r.id, p.id[i]) << i;
  EXPECT_EQ(r.type, static_cast<std::uint8_t>(p.type[i])) << i;
  EXPECT_EQ(r.material, p.material[i]) << i;
  EXPECT_EQ(r.vx, float(p.velocity[i].x)) << i;
  EXPECT_EQ(r.vy, float(p.velocity[i].y)) << i;
  EXPECT_EQ(r.vz, float(p.velocity[i].z)) << i;
}

constexpr std::size_t kFixedBytes = 3 * 4 + 3 + 4 + 1 + 2 + 3 * 4;

TEST_F(PlyPointsWriterTest, RoundTripsHeaderAndValuesExactly) {
  const Particles p = sample_particles();
  const fs::path file = dir_ / "frame_00001.ply";
  write_ply_points(file, p, {"density", "no.such.field", "accel", "density"});
  EXPECT_FALSE(fs::exists(dir_ / "frame_00001.ply.tmp"));

  const PlyFile f = parse_ply(file);
  EXPECT_EQ(f.header, header_for(4, {"density", "accel_x", "accel_y", "accel_z"}));
  ASSERT_EQ(f.body.size(), 4 * (kFixedBytes + 4 * 4));

  const auto* accel = p.find_vector("accel");
  std::size_t at = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    expect_fixed(take_record(f.body, at), p, i);
    EXPECT_EQ(take<float>(f.body, at), float((*p.find_scalar("density"))[i])) << i;
    EXPECT_EQ(take<float>(f.body, at), float((*accel)[i].x)) << i;
    EXPECT_EQ(take<float>(f.body, at), float((*accel)[i].y)) << i;
    EXPECT_EQ(take<float>(f.body, at), float((*accel)[i].z)) << i;
  }
  EXPECT_EQ(at, f.body.size());

  // Spot-check the bytes themselves, not just a round trip through the same layout: particle 2
  // is frozen, material 65535, id 2, at z = 1e6.
  const std::size_t rec = kFixedBytes + 4 * 4;
  const unsigned char* b = reinterpret_cast<const unsigned char*>(f.body.data()) + 2 * rec;
  EXPECT_EQ(std::vector<unsigned char>(b + 8, b + 12),
            (std::vector<unsigned char>{0x00, 0x24, 0x74, 0x49}));  // 1e6f, little-endian
  EXPECT_EQ(b[15], 2);                                              // id, low byte first
  EXPECT_EQ(b[19], 3);                                              // type frozen
  EXPECT_EQ(b[20], 0xFF);                                           // material 65535
  EXPECT_EQ(b[21], 0xFF);
}

TEST_F(PlyPointsWriterTest, IdsFollowParticlesAfterReordering) {
  Particles p = sample_particles();
  p.permute({3, 2, 0, 1});
  const fs::path file = dir_ / "permuted.ply";
  write_ply_points(file, p, {});
  const PlyFile f = parse_ply(file);
  EXPECT_EQ(f.header, header_for(4, {}));
  ASSERT_EQ(f.body.size(), 4 * kFixedBytes);
  std::size_t at = 0;
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Record r = take_record(f.body, at);
    expect_fixed(r, p, i);
    ids.push_back(r.id);
  }
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{3, 2, 0, 1}));
}

TEST_F(PlyPointsWriterTest, SkipsNamesThatWouldRepeatAProperty) {
  Particles p = sample_particles();
  p.scalar_field("x", Real(1), true);         // would repeat the position's x
  p.scalar_field("velocity", Real(1), true);  // a fixed VTK array: write_vtp skips it too
  p.scalar_field("a_y", Real(2), true);
  p.vector_field("a", Vec3{}, true);  // a_y already taken by the scalar before it
  p.scalar_field("two words", Real(4), true);
  write_ply_points(dir_ / "f.ply", p, {"x", "velocity", "a_y", "a", "two words", "id"});
  const PlyFile f = parse_ply(dir_ / "f.ply");
  EXPECT_EQ(f.header, header_for(4, {"a_y", "two_words"}));
  EXPECT_EQ(f.body.size(), 4 * (kFixedBytes + 2 * 4));
}

TEST_F(PlyPointsWriterTest, PropertyNamesAreSingleAsciiTokens) {
  EXPECT_EQ(ply_property_name("pcisph.pressure"), "pcisph.pressure");
  EXPECT_EQ(ply_property_name("a b\tc\nd"), "a_b_c_d");
  EXPECT_EQ(ply_property_name("caf\xc3\xa9"), "caf__");
  EXPECT_EQ(ply_property_name(""), "_");
}

TEST_F(PlyPointsWriterTest, NoParticlesGivesAValidEmptyCloud) {
  Particles p;
  write_ply_points(dir_ / "empty.ply", p, {"density"});
  const PlyFile f = parse_ply(dir_ / "empty.ply");
  EXPECT_EQ(f.header, header_for(0, {}));
  EXPECT_TRUE(f.body.empty());
}

TEST_F(PlyPointsWriterTest, ManyParticlesSpanSeveralWriteBlocks) {
  // The writer buffers 4096 vertices at a time: cross two block boundaries.
  Particles p;
  constexpr int kCount = 9000;
  for (int i = 0; i < kCount; ++i)
    p.add({Real(i), Real(-i), Real(i) / 8}, {Real(i) / 4, 0, 1}, 1, ParticleType(i % 4),
          MaterialId(i % 5));
  p.scalar_field("s", Real(0), true);
  for (int i = 0; i < kCount; ++i) p.scalar_field("s")[std::size_t(i)] = Real(i) * 2;
  write_ply_points(dir_ / "big.ply", p, {"s"});
  const PlyFile f = parse_ply(dir_ / "big.ply");
  EXPECT_EQ(f.header, header_for(kCount, {"s"}));
  ASSERT_EQ(f.body.size(), kCount * (kFixedBytes + 4));
  std::size_t at = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    expect_fixed(take_record(f.body, at), p, i);
    ASSERT_EQ(take<float>(f.body, at), float(2 * i)) << i;
  }
}

TEST_F(PlyPointsWriterTest, ReplacesAnOldFileAndReportsAMissingDirectory) {
  write_text(dir_ / "f.ply", "old");
  write_ply_points(dir_ / "f.ply", sample_particles(), {});
  EXPECT_EQ(parse_ply(dir_ / "f.ply").header, header_for(4, {}));

  const fs::path missing = dir_ / "no_such_dir" / "f.ply";
  const std::string msg =
      output_error_message([&] { write_ply_points(missing, sample_particles(), {}); });
  EXPECT_NE(msg.find(missing.string()), std::string::npos) << msg;
}

TEST(TypePalette, EveryTypeHasItsOwnColour) {
  std::set<std::uint32_t> seen;
  for (int t = 0; t < kParticleTypeCount; ++t) {
    const Rgb8 c = type_colour(static_cast<ParticleType>(t));
    EXPECT_NE(c, kUnknownTypeColour) << t;
    seen.insert(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
  }
  EXPECT_EQ(seen.size(), std::size_t(kParticleTypeCount));
  // The liquid is blue and the walls grey, as the docs say.
  const Rgb8 liquid = type_colour(ParticleType::Liquid);
  EXPECT_GT(liquid.b, liquid.r);
  const Rgb8 frozen = type_colour(ParticleType::Frozen);
  EXPECT_TRUE(frozen.r == frozen.g && frozen.g == frozen.b);
  EXPECT_EQ(type_colour(static_cast<ParticleType>(200)), kUnknownTypeColour);
}

}  // namespace
}  // namespace upf
