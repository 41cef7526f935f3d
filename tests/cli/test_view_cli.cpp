// `upf view`: the interactive viewer, driven in its scripted mode (--screenshot, --exit-after)
// under a virtual X server (xvfb-run), for a scene stepped live and for a saved run. The window's
// pixels are decoded (stb_image): the requested size, and not blank. Without a display it says
// so (exit code 1); a missing input is exit code 2.
#include <cmath>
#include <cstdlib>

#include "cli_support.h"
#include "picture_check.h"

namespace upf::cli_test {
namespace {

bool have_xvfb() {
  return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

class View : public Cli {
 protected:
  // Runs `upf view INPUT` under xvfb-run, scripted: 3 frames, then a 640x360 screenshot.
  void expect_screenshot(const std::string& input, const std::string& more = "") {
    const fs::path png = dir_ / "shot.png";
    const Result r = run_upf("view " + input + more + " --size 640x360 -j 2 --screenshot " +
                                 png.string() + " --exit-after 3",
                             "xvfb-run -a -s \"-screen 0 1024x768x24\"");
    ASSERT_EQ(r.code, 0) << r.output;
    const Picture s = decode_picture(png);
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 360);
    // The tank, the water and the panel give tens of grey levels; a blank window near 0.
    EXPECT_GT(s.luminance_std, 10.0);
  }
};

TEST_F(View, LiveSceneScreenshot) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  expect_screenshot(write(sample()), " --play");  // two ticks of stepping
}

TEST_F(View, SavedRunScreenshot) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const fs::path out = dir_ / "run";
  const Result r =
      run_upf("run " + write(sample()) + " --out " + out.string() + " --end 0.05 -q -j 2");
  ASSERT_EQ(r.code, 0) << r.output;
  expect_screenshot(out.string(), " --play");
}

TEST_F(View, WithoutDisplayExitsOneAndSaysSo) {
  const Result r = run_upf("view " + write(sample()) + " -j 2", "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("upf view needs a display (DISPLAY is not set); run it under xvfb-run "
                          "or use upf render"),
            std::string::npos)
      << r.output;
}

TEST_F(View, MissingInputIsBadInput) {
  const Result r = run_upf("view " + (dir_ / "nowhere.json").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("nowhere.json"), std::string::npos) << r.output;
}

TEST_F(View, BadSizeIsBadInput) {
  const Result r = run_upf("view " + write(sample()) + " --size big", "DISPLAY=");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace upf::cli_test
