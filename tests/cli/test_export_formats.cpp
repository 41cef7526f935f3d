// The frame formats as their real clients meet them: a small run's .pvd/.vtp series and .ply
// point clouds opened with VTK's own readers (vtkXMLPolyDataReader, as ParaView does, and
// vtkPLYReader) by tests/cli/check_vtk_series.py; the checker catches a corrupted frame; "ply"
// alone writes point clouds and no series; an unknown format is rejected with the known ones.
#include <cstring>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include "framework/compare/python_runner.h"
#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class ExportFormats : public Cli {
 protected:
  // Water at rest in a small closed tank: a 5 x 6 x 5 lattice of 150 liquid particles on the
  // tank's floor, inside 884 wall particles, which go once into frames/frozen.vtp and not into
  // the point clouds. fixed_dt = 1 / fps: the first step ends at the first
  // frame, so frame 1 holds the density the solver evaluated on the initial lattice (see
  // check_vtk_series.py).
  nlohmann::json tank() const {
    return nlohmann::json::parse(R"({
      "name": "tiny_tank",
      "gravity": [0, -9.81, 0],
      "particle_spacing": 0.02,
      "materials": {
        "water": { "type": "liquid", "density": 1000, "viscosity": 0.001, "solver": "pcisph" },
        "walls": { "type": "frozen" }
      },
      "containers": [ { "material": "walls", "min": [0, 0, 0], "max": [0.1, 0.2, 0.1] } ],
      "fluid_blocks": [ { "material": "water", "min": [0, 0, 0], "max": [0.1, 0.12, 0.1] } ],
      "time": { "end": 0.05, "fixed_dt": 0.002 },
      "output": { "fps": 500, "fields": ["density", "pressure"], "formats": ["vtp", "ply"],
                  "types": { "ply": ["liquid", "rigid", "granular"] } }
    })");
  }

  // Runs check_vtk_series.py on `out`: whether it passed, whether VTK's Python bindings were
  // missing (python3-vtk9, which scripts/install-deps skips when it conflicts with an installed
  // python3-paraview), and what it printed.
  struct VtkCheck {
    bool ok = false;
    bool no_vtk = false;
    std::string output;
  };
  VtkCheck check(const fs::path& out, const std::string& scene,
                 const std::string& density_tolerance) const {
    const fs::path log = dir_ / "check_vtk_series.log";
    fs::remove(log);
    const auto run =
        upf::run_python_script(fs::path(UPF_SOURCE_DIR) / "tests" / "cli" / "check_vtk_series.py",
                               {out.string(), scene, "1", density_tolerance}, log);
    return {run.ok, run.missing_module, run.error + "\n" + read_text(log)};
  }
};

// The SPH density sum over a full simple cubic lattice (m = rho0 s^3, cubic spline with support
// 2 s) is 0.9999725 rho0: the kernel's lattice-sum error, 2.8e-5. The tank's extents are
// multiples of the spacing, so its walls continue the lattice and, with their known lattice-cell
// volumes, stand in exactly for missing liquid: every liquid particle a support radius below the
// free surface measures 2.8e-5 low (the checker prints the worst), plus float rounding over ~30
// neighbours (~1e-6). 0.1 % is 36 times that, room for a boundary treatment that is not exactly
// lattice-consistent, and still fails a wrong particle mass, a missing wall contribution (tens of
// percent near the walls) or a field that is not the density. Particles within a support radius
// of the free surface only must not exceed it.
constexpr const char* kDensityTolerance = "0.001";

TEST_F(ExportFormats, VtkReadersOpenTheSeriesAndThePointClouds) {
  const std::string scene = write(tank());
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + scene + " --out " + out.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  ASSERT_TRUE(fs::exists(out / "frames" / "frame_00025.ply"));

  const auto [ok, no_vtk, output] = check(out, scene, kDensityTolerance);
  if (no_vtk) GTEST_SKIP() << "VTK's Python bindings are not installed: " << output;
  EXPECT_TRUE(ok) << output;
  std::cout << output;

  // The checker is not vacuous: a tighter density tolerance than the lattice gives fails, and
  // so does a point moved in one .ply.
  const auto [tight_ok, tight_no_vtk, tight] = check(out, scene, "1e-9");
  EXPECT_FALSE(tight_ok) << tight;
  EXPECT_NE(tight.find("density off rest density"), std::string::npos) << tight;

  const fs::path ply = out / "frames" / "frame_00003.ply";
  std::string bytes = read_text(ply);
  const std::size_t body = bytes.find("end_header\n") + std::strlen("end_header\n");
  ASSERT_LT(body + 4, bytes.size());
  const float moved = 123.0f;
  std::memcpy(bytes.data() + body, &moved, sizeof moved);  // the first point's x
  std::ofstream(ply, std::ios::binary) << bytes;
  const auto [moved_ok, moved_no_vtk, moved_output] = check(out, scene, kDensityTolerance);
  EXPECT_FALSE(moved_ok) << moved_output;
  EXPECT_NE(moved_output.find("frames/frame_00003.ply: 1 positions differ from the .vtp"),
            std::string::npos)
      << moved_output;
}

TEST_F(ExportFormats, PlyAloneWritesPointCloudsAndNoSeries) {
  auto doc = tank();
  doc["time"]["end"] = 0.004;
  doc["output"]["formats"] = {"ply"};
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"frame_00000.ply", "frame_00001.ply", "frame_00002.ply"})
    EXPECT_TRUE(fs::exists(out / "frames" / f)) << f;
  EXPECT_FALSE(fs::exists(out / "frames" / "frame_00003.ply"));
  EXPECT_FALSE(fs::exists(out / "frames" / "frame_00000.vtp"));
  EXPECT_FALSE(fs::exists(out / "particles.pvd")) << "the .pvd lists .vtp frames only";
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

// "vdb_points" and "surface_vdb": OpenVDB grids per frame (the read-back of every attribute by id,
// and of the level set against the mesh, is tests/unit/test_vdb_points.cpp), recorded in the
// run's manifest, not in the .pvd.
TEST_F(ExportFormats, VdbPointsAndLevelSetsWriteAGridPerFrameThatTheManifestRecords) {
  auto doc = tank();
  doc["time"]["end"] = 0.004;
  doc["output"]["formats"] = {"vtp", "vdb_points", "surface_vdb"};
  doc["output"]["vdb_compression"] = "fixed_point";
  doc["output"]["types"] = {{"vdb_points", {"liquid"}}};
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string manifest = read_text(out / "upf_manifest.txt");
  for (const char* f : {"points_00000.vdb", "points_00001.vdb", "points_00002.vdb",
                        "surface_00000.vdb", "surface_00002.vdb"}) {
    const std::string bytes = read_text(out / "frames" / f);
    ASSERT_GT(bytes.size(), 8u) << f;
    EXPECT_EQ(bytes.substr(0, 4), std::string(" BDV")) << f << ": OpenVDB's magic number";
    EXPECT_NE(manifest.find(std::string("f frames/") + f), std::string::npos) << f;
  }
  EXPECT_EQ(read_text(out / "particles.pvd").find(".vdb"), std::string::npos);
  doc["output"]["vdb_compression"] = "zip";
  expect_rejected(doc, {":/output/vdb_compression", "\"none\", \"truncate\", \"fixed_point\""});
}

// "/output/surface_method" picks the surfacing of "surface" (framework/output/liquid_surface.h):
// the anisotropic kernels by default, the union of spheres on request; anything else is refused.
TEST_F(ExportFormats, SurfaceMethodPicksTheSurfacing) {
  auto doc = tank();
  doc["time"]["end"] = 0.001;
  doc["output"]["formats"] = {"surface"};
  const fs::path smooth = dir_ / "smooth";
  Result r = run_upf("run " + write(doc) + " --out " + smooth.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  doc["output"]["surface_method"] = "spheres";
  const fs::path spheres = dir_ / "spheres";
  r = run_upf("run " + write(doc) + " --out " + spheres.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string a = read_text(smooth / "frames" / "surface_00000.ply");
  const std::string b = read_text(spheres / "frames" / "surface_00000.ply");
  ASSERT_GT(a.size(), 200u);
  ASSERT_GT(b.size(), 200u);
  EXPECT_NE(a, b);
  doc["output"]["surface_method"] = "bumps";
  expect_rejected(doc, {":/output/surface_method", "\"anisotropic\", \"spheres\""});
}

// "/output/surface_voxel" sets the surface's voxel (a finer voxel, a finer mesh), and a voxel
// whose grids would pass "/output/surface_memory" is refused before the first step, with exit
// code 2, the key, the estimate and a voxel that fits; an earlier run's frames stay.
TEST_F(ExportFormats, SurfaceVoxelIsBoundedByTheSurfaceMemory) {
  auto doc = tank();
  doc["time"]["end"] = 0.001;
  doc["output"]["formats"] = {"surface"};
  const fs::path coarse = dir_ / "coarse";
  Result r = run_upf("run " + write(doc) + " --out " + coarse.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  doc["output"]["surface_voxel"] = 0.25;
  const fs::path fine = dir_ / "fine";
  r = run_upf("run " + write(doc) + " --out " + fine.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  // About four times the triangles at half the voxel.
  const auto size = [](const fs::path& f) { return double(fs::file_size(f)); };
  const double ratio =
      size(fine / "frames" / "surface_00000.ply") / size(coarse / "frames" / "surface_00000.ply");
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.5);

  // 150 liquid particles at a voxel of 0.25 spacings: 8 * 150 * 64 = 76,800 bytes; the voxel
  // that fits 50,000 is 0.25 * cbrt(76,800 / 50,000) = 0.288 spacings.
  doc["output"]["surface_memory"] = 5e-5;
  const std::string before = read_text(fine / "frames" / "surface_00000.ply");
  r = run_upf("run " + write(doc) + " --out " + fine.string() + " --overwrite --threads 1 -q");
  EXPECT_EQ(r.code, 2) << r.output;
  for (const char* needle : {":/output/surface_voxel", "7.68e-05 GB", "/output/surface_memory",
                             "a voxel of at least 0.288 spacings fits"})
    EXPECT_NE(r.output.find(needle), std::string::npos) << needle << "\n" << r.output;
  EXPECT_EQ(read_text(fine / "frames" / "surface_00000.ply"), before);

  doc["output"]["surface_voxel"] = 0.01;
  expect_rejected(doc, {":/output/surface_voxel", "[0.05, 1]"});
}

// Blender 3.4's own PLY importer shows a point cloud without colours (it keeps colours only on
// faces); scripts/blender_upf.py opens the run with the colours and every property as point
// attributes, and follows the timeline (tests/cli/check_blender_import.py, in Blender headless).
TEST_F(ExportFormats, BlenderOpensThePointCloudsWithColoursAndAttributes) {
  if (run_shell("command -v blender").code != 0) GTEST_SKIP() << "Blender is not installed";
  auto doc = tank();
  doc["time"]["end"] = 0.01;
  doc["fluid_blocks"][0]["min"] = {0, 0.04, 0};  // falls, so frames differ
  doc["fluid_blocks"][0]["max"] = {0.1, 0.16, 0.1};
  doc["output"]["formats"] = {"ply"};
  doc["output"]["ply_up"] = "z";
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  const fs::path check = fs::path(UPF_SOURCE_DIR) / "tests" / "cli" / "check_blender_import.py";
  const Result b = run_shell("blender -b --factory-startup --python-exit-code 1 --python " +
                             check.string() + " -- " + out.string());
  EXPECT_EQ(b.code, 0) << b.output;
  EXPECT_NE(b.output.find("blender import ok"), std::string::npos) << b.output;
}

// Blender 3.4 reads a "surface_vdb" level set (File > Import > OpenVDB) and its Volume to Mesh
// modifier at threshold 0 meshes it where upf's own mesh lies
// (tests/cli/check_blender_level_set.py).
TEST_F(ExportFormats, BlenderMeshesTheLevelSetWhereTheSurfaceMeshLies) {
  if (run_shell("command -v blender").code != 0) GTEST_SKIP() << "Blender is not installed";
  auto doc = tank();
  doc["time"]["end"] = 0.002;
  doc["output"]["formats"] = {"surface", "surface_vdb"};
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  const fs::path check = fs::path(UPF_SOURCE_DIR) / "tests" / "cli" / "check_blender_level_set.py";
  const Result b = run_shell("blender -b --factory-startup --python-exit-code 1 --python " +
                             check.string() + " -- " + out.string());
  EXPECT_EQ(b.code, 0) << b.output;
  EXPECT_NE(b.output.find("blender level set ok"), std::string::npos) << b.output;
}

// "ply_up": "z" turns the point clouds Z-up for Blender: (x, y, z) -> (x, -z, y), velocities
// alike; the .vtp keeps the scene's Y-up axes.
TEST_F(ExportFormats, PlyUpZTurnsThePointCloudsAndNotTheVtp) {
  auto doc = tank();
  doc["time"]["end"] = 0.004;
  doc["output"]["types"] = {{"ply", {"liquid"}}, {"vtp", {"liquid"}}};
  const fs::path y_up = dir_ / "y", z_up = dir_ / "z";
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + y_up.string() + " -j1 -q").code, 0);
  doc["output"]["ply_up"] = "z";
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + z_up.string() + " -j1 -q").code, 0);
  EXPECT_EQ(read_text(y_up / "frames" / "frame_00002.vtp"),
            read_text(z_up / "frames" / "frame_00002.vtp"));
  const std::string a = read_text(y_up / "frames" / "frame_00002.ply"),
                    b = read_text(z_up / "frames" / "frame_00002.ply");
  const std::size_t body = a.find("end_header\n") + std::strlen("end_header\n");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(body + 150 * 42, a.size()) << "150 liquid particles of 42 bytes (density, pressure)";
  auto at = [](const std::string& bytes, std::size_t offset) {
    float v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
  };
  // Per vertex: x y z (floats at 0, 4, 8), r g b, id, type, material (10 bytes), vx vy vz at 22.
  for (std::size_t i = 0; i < 150; ++i) {
    const std::size_t v = body + i * 42;
    EXPECT_EQ(at(b, v), at(a, v));
    EXPECT_EQ(at(b, v + 4), -at(a, v + 8));
    EXPECT_EQ(at(b, v + 8), at(a, v + 4));
    EXPECT_EQ(at(b, v + 22 + 4), -at(a, v + 22 + 8));
    EXPECT_EQ(at(b, v + 22 + 8), at(a, v + 22 + 4));
  }
}

// /output/types and the layout keys are checked like the rest of the scene.
TEST_F(ExportFormats, BadLayoutKeysAreRefusedWithTheirPaths) {
  auto doc = tank();
  doc["output"]["types"] = {{"ply", {"liquid", "water"}}, {"obj", {"liquid"}}};
  doc["output"]["compression"] = "gzip";
  doc["output"]["frozen"] = "sometimes";
  doc["output"]["ply_up"] = "x";
  expect_rejected(doc, {"/output/types/ply/1", "unknown particle type \"water\"", "/output/types",
                        "obj", "/output/compression", "\"gzip\"", "/output/frozen", "\"once\"",
                        "/output/ply_up", "\"z\""});
}

// The estimate `upf run` prints before its first step is the bytes the particle files then take
// uncompressed (less their XML, under 1 kB a file), and an upper bound with compression; over
// /output/size_warning it warns, naming the key.
TEST_F(ExportFormats, SizeEstimateIsWhatTheFramesTake) {
  auto doc = sample();  // the dam break at 5 cm: 1536 liquid and 6396 wall particles
  doc["time"]["end"] = 0.1;
  doc["output"]["formats"] = {"vtp", "ply"};
  doc["output"]["compression"] = "none";
  auto estimate_and_bytes = [&](const nlohmann::json& scene, const fs::path& out) {
    const Result r = run_upf("run " + write(scene) + " -o " + out.string() + " -j2");
    EXPECT_EQ(r.code, 0) << r.output;
    const std::regex line("frames: (\\d+) x [^=]+= (at most )?([0-9.]+) (B|kB|MB)");
    std::smatch m;
    EXPECT_TRUE(std::regex_search(r.output, m, line)) << r.output;
    const double unit = m[4] == "MB" ? 1e6 : (m[4] == "kB" ? 1e3 : 1);
    double bytes = 0;
    for (const auto& e : fs::directory_iterator(out / "frames")) bytes += double(e.file_size());
    return std::pair{std::stod(m[3]) * unit, bytes};
  };
  const auto [estimate, bytes] = estimate_and_bytes(doc, dir_ / "raw");
  EXPECT_GE(bytes, estimate * 0.995);  // three digits printed
  EXPECT_LE(bytes, estimate * 1.02);
  doc["output"]["compression"] = "zlib";
  const auto [bound, packed] = estimate_and_bytes(doc, dir_ / "zlib");
  EXPECT_DOUBLE_EQ(bound, estimate);
  EXPECT_LT(packed, bound);

  doc["output"]["size_warning"] = 0.0001;  // 100 kB
  const Result warned = run_upf("run " + write(doc) + " -o " + (dir_ / "w").string() + " -q");
  EXPECT_EQ(warned.code, 0) << warned.output;
  EXPECT_NE(warned.output.find("warning: the frames may take at most"), std::string::npos)
      << warned.output;
  EXPECT_NE(warned.output.find(":/output/size_warning (0.0001 GB)"), std::string::npos)
      << warned.output;
}

TEST_F(ExportFormats, UnknownFormatListsTheKnownOnes) {
  auto doc = tank();
  doc["output"]["formats"] = {"ply", "obj", 3};
  expect_rejected(doc, {"/output/formats/1", "unknown format \"obj\"", "/output/formats/2",
                        "\"vtp\"", "\"ply\""});
}

}  // namespace
