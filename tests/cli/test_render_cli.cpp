// `upf render` and `upf run --render`: pictures of a small run, checked by decoding them
// (stb_image): the requested size, not blank (the pixel values vary), one per frame, and an MP4
// when ffmpeg is installed. Bad requests are exit code 2 naming the culprit.
#include <cmath>
#include <fstream>

#include "cli_support.h"
#include "picture_check.h"

namespace upf::cli_test {
namespace {

class Render : public Cli {
 protected:
  // A 0.05 m dam break for 0.2 s at 10 frames per second: 3 frames.
  std::string small_run() {
    auto doc = sample();
    doc["time"]["end"] = 0.2;
    doc["output"]["fps"] = 10;
    return write(doc);
  }
};

TEST_F(Render, RunWithRenderDrawsEveryFrameAtTheRequestedSize) {
  const fs::path out = dir_ / "run";
  const Result r = run_upf("run " + small_run() + " --out " + out.string() +
                           " -q -j 2 --render --size 320x180 --color-by speed");
  ASSERT_EQ(r.code, 0) << r.output;
  int frames = 0;
  for (const auto& e : fs::directory_iterator(out / "frames"))
    frames +=
        e.path().filename().string().rfind("frame_", 0) == 0 && e.path().extension() == ".vtp";
  ASSERT_EQ(frames, 3);
  for (int k = 0; k < frames; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    const Picture p = decode_picture(out / "render" / name);
    EXPECT_EQ(p.width, 320) << name;
    EXPECT_EQ(p.height, 180) << name;
    // A blank or nearly blank picture has a standard deviation near 0; the tank, the water and
    // the colour bar give tens of grey levels.
    EXPECT_GT(p.luminance_std, 10.0) << name;
  }
  EXPECT_NE(r.output.find("coloured by speed"), std::string::npos) << r.output;
  if (std::system("command -v ffmpeg >/dev/null 2>&1") == 0) {
    std::ifstream video(out / "render" / "dam_break.mp4", std::ios::binary);
    char header[8] = {};
    video.read(header, 8);
    EXPECT_EQ(std::string(header + 4, 4), "ftyp") << "not an MP4 file";
  }
  // Rendering again with other options replaces the pictures; a frame range draws only those.
  const Result again = run_upf("render " + out.string() +
                               " --frames 1:1 --size 200x100 --no-video -q --color-by density");
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_EQ(decode_picture(out / "render" / "frame_00001.png").width, 200);
  EXPECT_EQ(decode_picture(out / "render" / "frame_00000.png").width, 320);
}

// The sample's render section colours speed over [0, 4]: that range belongs to speed. Colouring
// by pressure gets the pressure's own percentile range, printed with its unit (before, pressure
// was drawn over [0, 4] Pa: one colour). Without a terminal, progress comes as plain lines.
TEST_F(Render, TheScenesRangeBelongsToItsOwnField) {
  const fs::path out = dir_ / "run";
  ASSERT_EQ(run_upf("run " + small_run() + " --out " + out.string() + " -q -j 2").code, 0);
  const Result own = run_upf("render " + out.string() + " --size 160x90 --no-video -q");
  ASSERT_EQ(own.code, 0) << own.output;
  EXPECT_NE(own.output.find("coloured by speed (m/s) from 0 to 4: the scene's render.range"),
            std::string::npos)
      << own.output;

  const Result other =
      run_upf("render " + out.string() + " --size 160x90 --no-video --color-by pressure");
  ASSERT_EQ(other.code, 0) << other.output;
  EXPECT_NE(other.output.find("coloured by pressure (Pa) from "), std::string::npos)
      << other.output;
  EXPECT_NE(other.output.find("1st-99th percentile over the frames"), std::string::npos)
      << other.output;
  EXPECT_EQ(other.output.find("from 0 to 4"), std::string::npos) << other.output;
  EXPECT_NE(other.output.find("rendering frame 1/3\n"), std::string::npos) << other.output;
  EXPECT_EQ(other.output.find('\r'), std::string::npos) << other.output;
}

TEST_F(Render, BadRequestsAreBadInputNamingTheCulprit) {
  const fs::path out = dir_ / "run";
  ASSERT_EQ(run_upf("run " + small_run() + " --out " + out.string() + " -q --end 0.05").code, 0);
  struct Case {
    std::string args, needle;
  };
  for (const Case& c :
       std::vector<Case>{{"render " + out.string() + " --color-by vorticity", "vorticity"},
                         {"render " + out.string() + " --size 10x10", "--size"},
                         {"render " + out.string() + " --frames 7", "--frames"},
                         {"render " + (dir_ / "nowhere").string(), "particles.pvd"},
                         {"render " + out.string() + " --range 2,1", "--range"}}) {
    const Result r = run_upf(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.needle), std::string::npos) << c.args << "\n" << r.output;
  }
  // A bad "render" section is caught before the run, by the scene reader.
  auto doc = sample();
  doc["render"] = {{"camera", {{"position", {1, 1, 1}}, {"target", {1, 1, 1}}}}, {"walls", "fog"}};
  expect_rejected(doc, {"/render/camera/target", "/render/walls", "fog"});
}

// --surface draws the liquid as water: its surface meshes ("surface" frames) shaded with
// refraction and absorption, the liquid's particles hidden. The same frame with the particles
// coloured by a speed range above every speed is viridis' dark purple, with no blue at all; as
// water, a good part of the tank is blue. A run without surface meshes is refused, naming the
// scene key to add.
TEST_F(Render, SurfaceDrawsTheLiquidAsWater) {
  auto doc = sample();
  doc["time"]["end"] = 0.1;
  doc["output"]["fps"] = 10;
  doc["output"]["formats"] = {"vtp", "surface"};
  const fs::path out = dir_ / "run";
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + out.string() + " -q -j2").code, 0);
  const std::string draw = "render " + out.string() + " --frames 1 --no-video --size 320x180 " +
                           "--walls hidden -q --color-by speed --range 100,200 -o ";
  const Result water = run_upf(draw + (dir_ / "water").string() + " --surface");
  ASSERT_EQ(water.code, 0) << water.output;
  const Result speed = run_upf(draw + (dir_ / "speed").string());
  ASSERT_EQ(speed.code, 0) << speed.output;
  const Picture w = decode_picture(dir_ / "water" / "frame_00001.png");
  const Picture s = decode_picture(dir_ / "speed" / "frame_00001.png");
  ASSERT_EQ(w.width, 320);
  EXPECT_GT(w.blue_fraction, 0.05) << "the water covers part of the picture";
  EXPECT_LT(s.blue_fraction, 0.01) << "below the range, viridis gives dark purple particles";
  EXPECT_GT(w.luminance_std, 5.0);

  doc["output"]["formats"] = {"vtp"};
  const fs::path bare = dir_ / "bare";
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + bare.string() + " -q -j2").code, 0);
  const Result refused = run_upf("render " + bare.string() + " --surface --no-video -q");
  EXPECT_EQ(refused.code, 2) << refused.output;
  EXPECT_NE(refused.output.find("add \"surface\" to the scene's /output/formats"),
            std::string::npos)
      << refused.output;
}

}  // namespace
}  // namespace upf::cli_test
