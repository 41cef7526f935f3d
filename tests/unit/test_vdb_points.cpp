// The OpenVDB frames (issue 43), read back through OpenVDB's own reader (io::File):
// - VDB points (framework/output/vdb_points_writer.h): every attribute matches the particle it
//   came from, found by its id: exactly without compression, and within each codec's stated
//   bound otherwise (the codecs' quantisation: a half's 11-bit significand, a 16-bit fixed point
//   over one voxel);
// - the surface's level set (liquid_surface.h, "surface_vdb"): its zero level lies within half a
//   voxel of every vertex of the mesh made by the same surfacing.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/tools/Interpolation.h>

#include "framework/output/liquid_surface.h"
#include "framework/output/vdb_points_writer.h"
#include "framework/particles/particles.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
namespace vp = openvdb::points;

constexpr double kSpacing = 0.02;

// Liquid and frozen particles scattered over a 0.5 m box (off any lattice), with a scalar and a
// vector field, and ids with gaps (some particles removed).
Particles scattered_particles() {
  Particles p;
  const auto density = p.declare_scalar("density", 0, true);
  const auto vorticity = p.declare_vector("vorticity", Vec3{}, true);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> at(-0.2, 0.3), speed(-3, 3), rho(950, 1100);
  for (int k = 0; k < 3000; ++k)
    p.add(Vec3{Real(at(rng)), Real(at(rng)), Real(at(rng))},
          Vec3{Real(speed(rng)), Real(speed(rng)), Real(speed(rng))}, Real(0.008),
          k % 5 == 0 ? ParticleType::Frozen : ParticleType::Liquid, MaterialId(k % 5 == 0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    p[density][i] = Real(rho(rng));
    p[vorticity][i] = Vec3{Real(speed(rng)), Real(speed(rng)), Real(speed(rng))};
  }
  std::vector<std::uint8_t> doomed(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); i += 7) doomed[i] = 1;
  p.remove(doomed);
  return p;
}

struct ReadBack {
  openvdb::Vec3d position;
  openvdb::Vec3f velocity, vorticity;
  std::int32_t type = 0, material = 0;
  float density = 0;
};

// Every point of the grid "points" in `file`, by id, through OpenVDB's reader.
std::map<std::int64_t, ReadBack> read_points(const fs::path& file, double& voxel) {
  openvdb::initialize();
  openvdb::io::File in(file.string());
  in.open();
  const auto grid = openvdb::gridPtrCast<vp::PointDataGrid>(in.readGrid("points"));
  in.close();
  EXPECT_TRUE(grid);
  std::map<std::int64_t, ReadBack> points;
  if (!grid) return points;
  voxel = grid->transform().voxelSize()[0];
  for (auto leaf = grid->tree().cbeginLeaf(); leaf; ++leaf) {
    vp::AttributeHandle<openvdb::Vec3f> p(leaf->constAttributeArray("P"));
    vp::AttributeHandle<openvdb::Vec3f> v(leaf->constAttributeArray("v"));
    vp::AttributeHandle<openvdb::Vec3f> w(leaf->constAttributeArray("vorticity"));
    vp::AttributeHandle<std::int64_t> id(leaf->constAttributeArray("id"));
    vp::AttributeHandle<std::int32_t> type(leaf->constAttributeArray("type"));
    vp::AttributeHandle<std::int32_t> material(leaf->constAttributeArray("material"));
    vp::AttributeHandle<float> density(leaf->constAttributeArray("density"));
    for (auto i = leaf->beginIndexOn(); i; ++i) {
      ReadBack r;
      r.position = grid->transform().indexToWorld(p.get(*i) + i.getCoord().asVec3d());
      r.velocity = v.get(*i);
      r.vorticity = w.get(*i);
      r.type = type.get(*i);
      r.material = material.get(*i);
      r.density = density.get(*i);
      EXPECT_TRUE(points.emplace(id.get(*i), r).second) << "id " << id.get(*i) << " twice";
    }
  }
  return points;
}

struct Errors {
  double position = 0;   // largest, in voxels
  double attribute = 0;  // largest, relative to the value's magnitude
};

Errors write_and_compare(VdbPointsCodec codec) {
  const Particles p = scattered_particles();
  const fs::path file =
      fs::temp_directory_path() / ("upf_vdb_points_" + std::string(to_string(codec)) + ".vdb");
  write_vdb_points(file, p, {"density", "vorticity"}, kSpacing, codec);
  double voxel = 0;
  const auto points = read_points(file, voxel);
  fs::remove(file);
  EXPECT_EQ(voxel, vdb_points_voxel_size(kSpacing));
  EXPECT_EQ(points.size(), p.size());
  const auto& density = *p.find_scalar("density");
  const auto& vorticity = *p.find_vector("vorticity");
  Errors e;
  auto relative = [](double got, double want) { return std::abs(got - want) / std::abs(want); };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto it = points.find(std::int64_t(p.id[i]));
    if (it == points.end()) {
      ADD_FAILURE() << "id " << p.id[i] << " missing";
      continue;
    }
    const ReadBack& r = it->second;
    EXPECT_EQ(r.type, std::int32_t(p.type[i]));
    EXPECT_EQ(r.material, std::int32_t(p.material[i]));
    for (int k = 0; k < 3; ++k) {
      e.position = std::max(e.position, std::abs(r.position[k] - double(p.position[i][k])) / voxel);
      e.attribute = std::max(e.attribute, relative(r.velocity[k], p.velocity[i][k]));
      e.attribute = std::max(e.attribute, relative(r.vorticity[k], vorticity[i][k]));
    }
    e.attribute = std::max(e.attribute, relative(r.density, density[i]));
  }
  std::printf("%s: largest position error %.3g voxel (voxel %.4g m), attribute error %.3g\n",
              to_string(codec), e.position, voxel, e.attribute);
  return e;
}

TEST(VdbPoints, UncompressedAttributesReadBackExactlyById) {
  const Errors e = write_and_compare(VdbPointsCodec::none);
  EXPECT_EQ(e.position, 0.0);
  EXPECT_EQ(e.attribute, 0.0);
}

TEST(VdbPoints, TruncatedHalvesStayWithinTheirPrecision) {
  const Errors e = write_and_compare(VdbPointsCodec::truncate);
  EXPECT_LE(e.position, std::ldexp(1.0, -12));   // an offset in [-0.5, 0.5] as a half
  EXPECT_LE(e.attribute, std::ldexp(1.0, -11));  // half: 11 significant bits
  EXPECT_GT(e.attribute, 0.0) << "the codec changed nothing: not applied";
}

TEST(VdbPoints, FixedPointPositionsStayWithinAStepOfTheirVoxel) {
  const Errors e = write_and_compare(VdbPointsCodec::fixed_point);
  EXPECT_LE(e.position, std::ldexp(1.0, -16));  // 16 bits over one voxel
  EXPECT_GT(e.position, 0.0) << "the codec changed nothing: not applied";
  EXPECT_EQ(e.attribute, 0.0);
}

TEST(VdbPoints, TheVoxelIsAPowerOfTwoNearTwoSpacings) {
  EXPECT_EQ(vdb_points_voxel_size(0.02), 0.03125);
  EXPECT_EQ(vdb_points_voxel_size(0.01), 0.015625);
  EXPECT_EQ(vdb_points_voxel_size(0.5), 1.0);
}

// A ball of 3,000-odd particles at spacing 0.02 and a slab beside it: the level set written with
// the mesh of the same call, read back, sampled (trilinearly) at every mesh vertex.
TEST(SurfaceLevelSet, ItsZeroLevelIsTheMeshWithinHalfAVoxel) {
  const double h = 0.02;
  std::vector<Eigen::Vector3d> positions;
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j)
      for (int k = -10; k <= 10; ++k) {
        const Eigen::Vector3d x(i * h, j * h, k * h);
        if (x.norm() <= 0.18) positions.push_back(x);
        if (i < -6) positions.push_back(x + Eigen::Vector3d(0.5, 0, 0));  // a slab
      }
  const fs::path file = fs::temp_directory_path() / "upf_surface_level_set.vdb";
  const MeshPiece mesh = liquid_surface(positions, h, {}, {true, file});
  ASSERT_GT(mesh.vertices.size(), 1000u);

  openvdb::initialize();
  openvdb::io::File in(file.string());
  in.open();
  const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("surface"));
  in.close();
  fs::remove(file);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
  const double voxel = grid->voxelSize()[0];
  EXPECT_DOUBLE_EQ(voxel, 0.5 * h);
  const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> at(*grid);
  double largest = 0;
  for (const Eigen::Vector3d& v : mesh.vertices)
    largest = std::max(largest, std::abs(double(at.wsSample(openvdb::Vec3d(v.x(), v.y(), v.z())))));
  std::printf("level set at the mesh's %zu vertices: |phi| <= %.3g voxel\n", mesh.vertices.size(),
              largest / voxel);
  EXPECT_LE(largest, 0.5 * voxel);
  // Negative inside, positive outside: the ball's centre and a point well outside.
  EXPECT_LT(at.wsSample(openvdb::Vec3d(0, 0, 0)), 0.f);
  EXPECT_GT(at.wsSample(openvdb::Vec3d(0, 0.3, 0)), 0.f);
}

}  // namespace
}  // namespace upf
