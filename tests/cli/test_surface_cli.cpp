// The "surface" output format through the `upf` program: every frame gets the liquid's surface
// mesh as frames/surface_NNNNN.ply (binary PLY with faces) and frames/surface_NNNNN.vtp, the
// latter listed in particles.pvd as the last part of each time step; alone, "surface" writes a
// series of surfaces only; the unknown-format message lists it.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The number after "element NAME " in a PLY header; -1 if absent.
long ply_count(const std::string& ply, const std::string& element) {
  const std::string key = "element " + element + " ";
  const std::size_t at = ply.find(key);
  if (at == std::string::npos || at > ply.find("end_header")) return -1;
  return std::stol(ply.substr(at + key.size()));
}

class Surface : public Cli {
 protected:
  // Water at rest in a small closed tank (samples/hydrostatic_tank.json, shrunk): 5 x 4 x 5
  // liquid particles, 4 frames.
  nlohmann::json tank(const nlohmann::json& formats) const {
    auto doc = nlohmann::json::parse(R"({
      "name": "tiny_surface_tank",
      "gravity": [0, -9.81, 0],
      "particle_spacing": 0.02,
      "materials": {
        "water": { "type": "liquid", "density": 1000, "viscosity": 0.001, "solver": "pcisph" },
        "walls": { "type": "frozen" }
      },
      "containers": [ { "material": "walls", "min": [0, 0, 0], "max": [0.1, 0.14, 0.1] } ],
      "fluid_blocks": [ { "material": "water", "min": [0, 0, 0], "max": [0.1, 0.08, 0.1] } ],
      "time": { "end": 0.03, "dt_max": 0.002 },
      "output": { "fps": 100 }
    })");
    doc["output"]["formats"] = formats;
    return doc;
  }
};

TEST_F(Surface, EachFrameHasASurfaceMeshListedInTheSeries) {
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(tank({"vtp", "surface"})) + " --out " + out.string() +
                           " --threads 2 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string pvd = read_text(out / "particles.pvd");
  int frames = 0;
  for (;; ++frames) {
    char stem[32];
    std::snprintf(stem, sizeof stem, "%05d", frames);
    if (!fs::exists(out / "frames" / ("frame_" + std::string(stem) + ".vtp"))) break;
    const fs::path ply = out / "frames" / ("surface_" + std::string(stem) + ".ply");
    const fs::path vtp = out / "frames" / ("surface_" + std::string(stem) + ".vtp");
    ASSERT_TRUE(fs::exists(ply)) << ply;
    ASSERT_TRUE(fs::exists(vtp)) << vtp;
    const std::string text = read_text(ply);
    EXPECT_EQ(text.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << ply;
    // A closed surface around 100 particles: hundreds of triangles, never none.
    EXPECT_GT(ply_count(text, "vertex"), 100) << ply;
    EXPECT_GT(ply_count(text, "face"), 200) << ply;
    EXPECT_GT(fs::file_size(vtp), 0u);
    // Part 0 the particles, part 1 the frozen walls (written once), part 2 the surface.
    EXPECT_NE(pvd.find("part=\"1\" file=\"frames/frozen.vtp\""), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("part=\"2\" file=\"frames/surface_" + std::string(stem) + ".vtp\""),
              std::string::npos)
        << pvd;
  }
  EXPECT_GE(frames, 4) << "frames at t = 0, 0.01, 0.02, 0.03";
  EXPECT_FALSE(fs::exists(out / "frames" / "surface_00005.ply"));
}

TEST_F(Surface, AloneItWritesASeriesOfSurfaces) {
  const fs::path out = dir_ / "out";
  const Result r =
      run_upf("run " + write(tank({"surface"})) + " --out " + out.string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "frames" / "frame_00000.vtp"));
  EXPECT_TRUE(fs::exists(out / "frames" / "surface_00000.ply"));
  const std::string pvd = read_text(out / "particles.pvd");
  EXPECT_NE(pvd.find("part=\"0\" file=\"frames/surface_00000.vtp\""), std::string::npos) << pvd;
}

TEST_F(Surface, UnknownFormatListsSurfaceAmongTheKnown) {
  expect_rejected(tank({"vtp", "surfaces"}), {"/output/formats/1", "\"surface\"", "\"vtp\""});
}

}  // namespace
}  // namespace upf::cli_test
