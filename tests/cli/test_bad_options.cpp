// Command-line values that used to hang, pass silently or fail with the wrong exit code (issue 46,
// items 6 and 11): each is now bad input, exit code 2, naming the option. Commands that could
// hang on the old code run under `timeout -s KILL` (the wall-clock spin ignored SIGTERM).
#include <fstream>
#include <regex>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

class BadOptions : public Cli {
 protected:
  // `upf ARGS` from inside the test's directory (a default output folder lands there), killed
  // after `seconds`.
  Result upf_in_dir(const std::string& args, int seconds = 120) const {
    return run_shell("cd " + dir_.string() + " && timeout -s KILL " + std::to_string(seconds) +
                     " " + UPF_EXECUTABLE + " " + args);
  }
  // A short run's arguments: no frames, no progress, into the test's directory.
  std::string short_run(const std::string& scene) const {
    return scene + " -q --no-frames --out " + (dir_ / "out").string();
  }
  static void expect_bad_input(const Result& r, std::initializer_list<std::string> needles) {
    EXPECT_EQ(r.code, 2) << r.output;
    for (const auto& n : needles)
      EXPECT_NE(r.output.find(n), std::string::npos) << n << "\n" << r.output;
  }
};

TEST_F(BadOptions, TinyOrHugeCheckpointIntervalIsBadInputNotAHang) {
  // 1e-300s spun for ever at 100% CPU before the first step; 1e-300sim as well.
  const std::string scene = write(sample());
  expect_bad_input(upf_in_dir("run " + short_run(scene) + " --checkpoint-every 1e-300s", 60),
                   {"--checkpoint-every", "'1e-300s'", "allowed range",
                    "wall-clock intervals from 1 s to 1e+09 s"});
  expect_bad_input(upf_in_dir("run " + short_run(scene) + " --checkpoint-every 1e-300sim", 60),
                   {"--checkpoint-every", "simulated intervals from 1e-06 s"});
  expect_bad_input(upf_in_dir("run " + short_run(scene) + " --checkpoint-every 1e300h", 60),
                   {"--checkpoint-every", "allowed range"});
}

TEST_F(BadOptions, EndMustBeAFinitePositiveTimeWithinTheScenesRange) {
  // --end nan ran 0 steps and exited 0; inf would run for ever.
  const std::string scene = write(sample());
  for (const char* end : {"nan", "inf", "-1", "0", "1e30"})
    expect_bad_input(upf_in_dir("run " + short_run(scene) + " --end " + end, 60),
                     {"--end", "is not an end time", "(0, 1e+07] s"});
  expect_bad_input(upf_in_dir("compare " + scene + " --solvers pcisph --end nan -q", 60),
                   {"--end", "is not an end time"});
  // The check keeps what was allowed.
  EXPECT_EQ(upf_in_dir("run " + short_run(scene) + " --end 0.02").code, 0);
}

TEST_F(BadOptions, SetWithAnIndexBeyondSizeTNamesTheOption) {
  // The JSON library threw its own error: exit code 1 and no --set named.
  expect_bad_input(run_upf("validate " + write(sample()) +
                           " --set /containers/99999999999999999999999/layers=3"),
                   {"--set /containers/99999999999999999999999/layers=3", "the scene has no"});
}

TEST_F(BadOptions, SetWithANumberBeyondADoubleSaysSoAndNamesTheOption) {
  // 1e400 became the string "1e400": "expected a number, found a string", blamed on the file.
  const Result r = run_upf("validate " + write(sample()) + " --set /time/end=1e400");
  expect_bad_input(r, {"--set /time/end=1e400", "out of the representable range"});
  EXPECT_EQ(r.output.find("found a string"), std::string::npos) << r.output;
  expect_bad_input(run_upf("validate " + write(sample()) + " --set '/gravity=[0,-1e999,0]'"),
                   {"--set /gravity=[0,-1e999,0]", "out of the representable range"});
}

TEST_F(BadOptions, ValidateChecksTheGpuAsRunDoes) {
  // `validate --set /device=cuda` said ok on a machine where `run` stops for want of a GPU.
  const std::string scene = write(sample());
  const Result run =
      upf_in_dir("run " + short_run(scene) + " --set /device=cuda --end 0.005 -j 2", 300);
  const Result validate = run_upf("validate " + scene + " --set /device=cuda");
  if (run.code == 0) {
    EXPECT_EQ(validate.code, 0) << validate.output;  // a usable GPU: both go ahead
    return;
  }
  ASSERT_EQ(run.code, 2) << run.output;
  expect_bad_input(validate, {":/device", "'cuda'"});
}

TEST_F(BadOptions, EmptyOutIsBadInputForEveryCommand) {
  // -o '' silently meant the default folder.
  const std::string scene = write(sample());
  expect_bad_input(upf_in_dir("run " + scene + " -q --no-frames --end 0.005 -o ''", 60),
                   {"--out", "empty directory name"});
  expect_bad_input(upf_in_dir("compare " + scene + " --solvers pcisph --end 0.005 -q -o ''", 60),
                   {"--out", "empty directory name"});
  expect_bad_input(upf_in_dir("render " + (dir_ / "no_run").string() + " -q --out ''", 60),
                   {"--out", "empty directory name"});
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "nothing ran into a default folder";
}

TEST_F(BadOptions, ThreadsAreCappedAlikeEverywhere) {
  const std::string scene = write(sample());
  for (const std::string& command :
       {"run " + scene, "compare " + scene, "render " + dir_.string(), "view " + scene})
    for (const char* threads : {"0", "1025", "-3"})
      expect_bad_input(upf_in_dir(command + " --threads " + threads, 60), {"--threads"});
  // A plan's thread count comes from its file: checked there too.
  const fs::path split = dir_ / "split";
  ASSERT_EQ(upf_in_dir("compare " + scene + " --solvers pcisph --end 0.005 --no-frames -q " +
                       "--plan --out " + split.string())
                .code,
            0);
  nlohmann::json plan = nlohmann::json::parse(std::ifstream(split / "plan.json"));
  plan["threads"] = 100000;
  std::ofstream(split / "plan.json") << plan.dump(2);
  expect_bad_input(upf_in_dir("compare --task 0 -q --out " + split.string(), 60),
                   {"plan.json:/threads", "100000 threads", "0 (all) to 1024"});
}

TEST_F(BadOptions, ProgressPrintsHugeEtasInScientificNotation) {
  // A fixed step of 1e-300 s gives an ETA of ~1e297 s, printed with %.0f as 298 digits.
  // Without a terminal the first line comes after 4 s of stepping; SIGINT at 7 s stops the
  // run cleanly (a checkpoint, exit code 130).
  auto doc = sample();
  doc["time"]["fixed_dt"] = 1e-300;
  const Result r = run_shell("timeout -s INT 7 " + std::string(UPF_EXECUTABLE) + " run " +
                             write(doc) + " --no-frames --end 1 --out " + (dir_ / "out").string());
  if (r.code == 2) GTEST_SKIP() << "the scene's fixed_dt is refused now:\n" << r.output;
  ASSERT_NE(r.output.find("ETA"), std::string::npos) << r.output;
  EXPECT_FALSE(std::regex_search(r.output, std::regex("[0-9]{16}"))) << r.output;
  EXPECT_NE(r.output.find("e+"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace upf::cli_test
