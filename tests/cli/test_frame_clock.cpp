// Frames on the frame clock (issue: production output, item 3). Frame n is written at exactly
// t = n / fps, and a run's steps up to any time do not depend on `--end`: a preview's frames are
// byte for byte the first frames of the full shot, and `--resume --end` extends a finished run
// exactly as a run planned that long from the start. Before, the time left to the end was split
// evenly over all steps: runs of different lengths took different steps from the first one on,
// and frames fell up to 5 % of a frame interval off n / fps.
#include <fstream>
#include <iterator>
#include <regex>
#include <vector>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The `timestep` attributes of a .pvd, in file order.
std::vector<double> frame_times(const fs::path& pvd) {
  const std::string xml = text_of(pvd);
  // Part 0 of each time step (the frozen walls are part 1 of every step).
  const std::regex attribute("timestep=\"([^\"]+)\" group=\"\" part=\"0\"");
  std::vector<double> times;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), attribute);
       it != std::sregex_iterator(); ++it)
    times.push_back(std::stod((*it)[1].str()));
  return times;
}

class FrameClock : public Cli {
 protected:
  // The dam break at 5 cm with dt_max = 3 ms: 3 ms divides neither the frame interval (1/30 s)
  // nor the run lengths, so the old even split over the whole run gave 2.985 ms steps for
  // --end 0.2 and 3 ms steps for --end 0.3.
  std::string scene() {
    auto doc = sample();
    doc["time"]["dt_max"] = 0.003;
    return write(doc);
  }
  std::string frame(const fs::path& run, int n) const {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.vtp", n);
    return text_of(run / "frames" / name);
  }
};

TEST_F(FrameClock, FramesFallOnNOverFpsAndDoNotDependOnTheEnd) {
  const std::string s = scene();
  const fs::path preview = dir_ / "preview", shot = dir_ / "shot";
  ASSERT_EQ(run_upf("run " + s + " --end 0.2 -q -j2 -o " + preview.string()).code, 0);
  ASSERT_EQ(run_upf("run " + s + " --end 0.3 -q -j2 -o " + shot.string()).code, 0);

  const std::vector<double> times = frame_times(shot / "particles.pvd");
  ASSERT_EQ(times.size(), 10u);  // frames 0..9 at 30 fps
  for (std::size_t n = 0; n < times.size(); ++n)
    EXPECT_DOUBLE_EQ(times[n], double(n) / 30.0) << "frame " << n;

  for (int n = 0; n <= 6; ++n)
    EXPECT_TRUE(frame(preview, n) == frame(shot, n)) << "frame " << n << " differs";
}

TEST_F(FrameClock, ResumeWithALaterEndExtendsAFinishedRunExactly) {
  const std::string s = scene();
  const fs::path extended = dir_ / "extended", planned = dir_ / "planned";
  ASSERT_EQ(run_upf("run " + s + " --end 0.2 -q -j2 -o " + extended.string()).code, 0);
  ASSERT_EQ(run_upf("run " + s + " --end 0.3 -q -j2 -o " + planned.string()).code, 0);

  // A finished run says so instead of simulating again.
  const Result again = run_upf("run --resume " + extended.string());
  EXPECT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("already complete at t = 0.2000 s"), std::string::npos)
      << again.output;
  EXPECT_NE(again.output.find("--end T"), std::string::npos) << again.output;

  const Result longer = run_upf("run --resume " + extended.string() + " --end 0.3 -q -j1");
  ASSERT_EQ(longer.code, 0) << longer.output;
  for (int n = 0; n <= 9; ++n)
    EXPECT_TRUE(frame(extended, n) == frame(planned, n)) << "frame " << n << " differs";
  EXPECT_EQ(text_of(extended / "probes.csv"), text_of(planned / "probes.csv"));
  EXPECT_EQ(text_of(extended / "particles.pvd"), text_of(planned / "particles.pvd"));
}

}  // namespace
}  // namespace upf::cli_test
