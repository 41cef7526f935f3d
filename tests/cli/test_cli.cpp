// The `upf` program as a user meets it: bad input of every class gives exit code 2 and names the
// culprit (file and JSON path), an unstable run gives exit code 3 after writing the last good
// frame, and a good run writes its outputs.
#include <iterator>

#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

TEST_F(Cli, ValidSampleValidates) {
  const Result r =
      run_upf("validate " + (fs::path(UPF_SOURCE_DIR) / "samples" / "dam_break.json").string());
  EXPECT_EQ(r.code, 0) << r.output;
}

TEST_F(Cli, UnknownKeyNamesPathAndSuggestion) {
  auto doc = sample();
  doc["materials"]["water"]["viscosty"] = 0.01;
  expect_rejected(doc, {"/materials/water/viscosty", "did you mean 'viscosity'"});
}

TEST_F(Cli, WrongTypeNamesPath) {
  auto doc = sample();
  doc["time"]["end"] = "two seconds";
  expect_rejected(doc, {"/time/end", "expected a number"});
}

TEST_F(Cli, NonPositiveSpacingAndDensityAreRejectedTogether) {
  auto doc = sample();
  doc["particle_spacing"] = -0.01;
  doc["materials"]["water"]["density"] = 0;
  expect_rejected(doc, {"/particle_spacing", "/materials/water/density", "out of range"});
}

TEST_F(Cli, ARootCauseIsReportedOnce) {
  // A bad spacing or a material with a bad solver or type used to bring false follow-on errors
  // ("at least one particle spacing (1 m)", "no material named 'water'").
  auto count_problems = [&](const nlohmann::json& doc, const std::string& needle) {
    const Result r = run_upf("validate " + write(doc));
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(": 1 problem\n"), std::string::npos) << r.output;
  };
  auto doc = sample();
  doc["particle_spacing"] = "fine";
  count_problems(doc, "/particle_spacing: expected a number");
  doc = sample();
  doc["particle_spacing"] = -1;
  count_problems(doc, "/particle_spacing: value -1 is out of range");
  doc = sample();
  doc["materials"]["water"]["solver"]["name"] = "pcsph";
  count_problems(doc, "no solver named 'pcsph'");
  doc = sample();
  doc["materials"]["water"]["type"] = "liqid";
  count_problems(doc, "unknown material type 'liqid'");
  // A reference to a material the file does not declare is still an error.
  doc = sample();
  doc["fluid_blocks"][0]["material"] = "watr";
  expect_rejected(doc, {"no material named 'watr' (did you mean 'water'?)"});
}

TEST_F(Cli, FluidBlockOutsideContainer) {
  auto doc = sample();
  doc["fluid_blocks"][0]["max"] = {2.0, 0.8, 0.4};
  expect_rejected(doc, {"/fluid_blocks/0", "not inside any container"});
}

TEST_F(Cli, OverlappingFluidBlocksAreRefusedWithBothPaths) {
  // They passed validation and blew apart at step 2. Touching blocks stay allowed.
  auto doc = sample();
  auto second = doc["fluid_blocks"][0];
  const double width = second["max"][0].get<double>() - second["min"][0].get<double>();
  second["min"][0] = second["min"][0].get<double>() + 0.5 * width;
  second["max"][0] = second["max"][0].get<double>() + 0.5 * width;
  doc["fluid_blocks"].push_back(second);
  expect_rejected(doc, {"/fluid_blocks/1: overlaps /fluid_blocks/0"});
  doc["fluid_blocks"][1]["min"][0] = doc["fluid_blocks"][0]["max"][0];
  doc["fluid_blocks"][1]["max"][0] = doc["fluid_blocks"][0]["max"][0].get<double>() + 0.1;
  const Result touching = run_upf("validate " + write(doc));
  EXPECT_EQ(touching.code, 0) << touching.output;
}

TEST_F(Cli, TooManyParticlesForMemory) {
  auto doc = sample();
  doc["particle_spacing"] = 1e-5;
  doc["containers"][0]["layers"] = 1;
  expect_rejected(doc, {"/particle_spacing", "particles", "GiB"});
}

TEST_F(Cli, OutOfRangeSolverParameter) {
  auto doc = sample();
  doc["materials"]["water"]["solver"]["eta"] = 2.0;
  expect_rejected(doc, {"/materials/water/solver/eta", "[1e-06, 0.5]"});
}

TEST_F(Cli, MissingFileAndBrokenJson) {
  Result r = run_upf("validate " + (dir_ / "nope.json").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("nope.json: no such file"), std::string::npos) << r.output;
  const fs::path broken = dir_ / "broken.json";
  std::ofstream(broken) << "{\n  \"particle_spacing\": 0.02,\n  \"materials\": {,\n}";
  r = run_upf("run " + broken.string() + " --out " + (dir_ / "o").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("broken.json:3:"), std::string::npos) << r.output;
}

TEST_F(Cli, NumberBeyondADoubleIsNamedWithItsPlace) {
  // 1e400 overflows a double: the JSON parser names the token, not where it stands.
  const fs::path scene = dir_ / "huge.json";
  std::ofstream(scene) << "{\n  \"name\": \"x\",\n  \"particle_spacing\": 1e400\n}";
  const Result r = run_upf("validate " + scene.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("huge.json:3:23"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1e400 is out of range"), std::string::npos) << r.output;
}

TEST_F(Cli, SetOverridesAValueByJsonPointerAndTheRunRecordsIt) {
  // SPlisHSPlasH-style overrides: the value is checked like the file's and kept in the run's
  // record of its scene, upf_scene.json.
  auto doc = sample();
  const fs::path out = dir_ / "out";
  const std::string scene = write(doc);
  const Result r =
      run_upf("run --set /time/end=0.05 --set /materials/water/viscosity=0.01 " + scene +
              " --set /name=my_shot --out " + out.string() + " --threads 2 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream summary_file(out / "summary.json");
  const auto summary = nlohmann::json::parse(summary_file);
  EXPECT_NEAR(summary["simulated_time_s"].get<double>(), 0.05, 1e-12);
  std::ifstream recorded_file(out / "upf_scene.json");
  const auto recorded = nlohmann::json::parse(recorded_file);
  EXPECT_EQ(recorded["materials"]["water"]["viscosity"], 0.01);
  EXPECT_EQ(recorded["name"], "my_shot");  // not JSON: taken as a string
  EXPECT_EQ(summary["scene"], "my_shot");
  EXPECT_EQ(recorded["time"]["end"], 0.05);

  // A value out of range is named by its JSON path; a missing parent or a bad pointer by --set.
  Result bad = run_upf("validate " + scene + " --set /materials/water/density=-1");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("/materials/water/density"), std::string::npos) << bad.output;
  bad = run_upf("validate " + scene + " --set /materials/oil/density=900");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("--set /materials/oil/density=900: the scene has no /materials/oil"),
            std::string::npos)
      << bad.output;
  bad = run_upf("validate " + scene + " --set time/end=1");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("is not a JSON pointer"), std::string::npos) << bad.output;
  bad = run_upf("validate " + scene + " --set /fluid_blocks/3={}");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("no index 3"), std::string::npos) << bad.output;
}

TEST_F(Cli, HelpShowsExamplesAndExitCodesWithoutParserClutter) {
  const Result main_help = run_upf("--help");
  EXPECT_EQ(main_help.code, 0) << main_help.output;
  for (const char* s : {"Examples:", "upf run samples/dam_break.json", "Exit codes: 0 ok",
                        "2 bad input", "3 unstable"})
    EXPECT_NE(main_help.output.find(s), std::string::npos) << s << "\n" << main_help.output;
  const Result run_help = run_upf("run --help");
  EXPECT_EQ(run_help.code, 0) << run_help.output;
  for (const char* s : {"--threads N", "--end T", "--set PTR=VALUE", "Examples:", "Exit codes"})
    EXPECT_NE(run_help.output.find(s), std::string::npos) << s << "\n" << run_help.output;
  for (const char* clutter : {"Excludes:", "INT:INT", "FLOAT:POSITIVE", "TEXT"})
    EXPECT_EQ(run_help.output.find(clutter), std::string::npos) << clutter << "\n"
                                                                << run_help.output;
  // The checks the annotations described still hold.
  const Result bad = run_upf("run " + write(sample()) + " --threads 0");
  EXPECT_NE(bad.code, 0);
}

TEST_F(Cli, RunWritesOutputs) {
  auto doc = sample();
  doc["time"]["end"] = 0.1;
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " --threads 2 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"particles.pvd", "metrics.csv", "probes.csv", "summary.json",
                        "frames/frame_00000.vtp", "frames/frame_00003.vtp"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  std::ifstream summary(out / "summary.json");
  const auto s = nlohmann::json::parse(summary);
  EXPECT_EQ(s["status"], "completed");
  EXPECT_NEAR(s["simulated_time_s"].get<double>(), 0.1, 1e-9);
  // By default a run uses a thread per free core (thread_share_watch.h): between 1 and the 2
  // asked for, however busy the machine. --fixed-threads keeps both, and the bits are the same.
  EXPECT_GE(s["mean_threads"].get<double>(), 1.0);
  EXPECT_LE(s["mean_threads"].get<double>(), 2.0);
  const fs::path fixed = dir_ / "fixed";
  const Result f =
      run_upf("run " + write(doc) + " --out " + fixed.string() + " --threads 2 --fixed-threads -q");
  ASSERT_EQ(f.code, 0) << f.output;
  std::ifstream fixed_summary(fixed / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(fixed_summary)["mean_threads"].get<double>(), 2.0);
  for (const char* file : {"probes.csv", "frames/frame_00003.vtp"}) {
    std::ifstream a(out / file, std::ios::binary), b(fixed / file, std::ios::binary);
    const std::string bytes_a{std::istreambuf_iterator<char>(a), {}};
    const std::string bytes_b{std::istreambuf_iterator<char>(b), {}};
    EXPECT_FALSE(bytes_a.empty()) << file;
    EXPECT_EQ(bytes_a, bytes_b) << file;
  }
}

// probes.csv gets a row at every step (an impact lasts a few steps, not a few frames), and at
// every frame; /output/probe_every thins the steps, 0 leaves the frames only. The step rows'
// times are metrics.csv's.
TEST_F(Cli, ProbesAreSampledEveryStepOrAsThinnedOrAtFrames) {
  // The values of column `column` (probes.csv: 0 is the time; metrics.csv: 1).
  auto rows = [](const fs::path& csv, int column = 0) {
    std::ifstream in(csv);
    std::vector<double> times;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::size_t at = 0;
      for (int c = 0; c < column; ++c) at = line.find(',', at) + 1;
      times.push_back(std::stod(line.substr(at, line.find(',', at) - at)));
    }
    return times;
  };
  auto doc = sample();
  doc["time"]["end"] = 0.1;  // frames at 0, 1/30, 2/30 and 0.1
  const fs::path every = dir_ / "every", fifth = dir_ / "fifth", frames = dir_ / "frames";
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + every.string() + " -j2 -q").code, 0);
  doc["output"]["probe_every"] = 5;
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + fifth.string() + " -j2 -q").code, 0);
  doc["output"]["probe_every"] = 0;
  ASSERT_EQ(run_upf("run " + write(doc) + " -o " + frames.string() + " -j2 -q").code, 0);

  const std::vector<double> steps = rows(every / "metrics.csv", 1);
  ASSERT_GT(steps.size(), 20u);
  const std::vector<double> sampled = rows(every / "probes.csv");
  ASSERT_EQ(sampled.size(), steps.size() + 1) << "frame 0, then every step";
  EXPECT_EQ(sampled[0], 0.0);
  for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_NEAR(sampled[k + 1], steps[k], 1e-8);
  EXPECT_EQ(rows(frames / "probes.csv").size(), 4u) << "the four frames";
  // Every fifth step, plus the frames that fall between.
  const std::vector<double> thinned = rows(fifth / "probes.csv");
  EXPECT_GT(thinned.size(), steps.size() / 5);
  EXPECT_LT(thinned.size(), steps.size() / 5 + 5);
  double previous = -1;
  for (double t : thinned) {
    EXPECT_GT(t, previous);
    previous = t;
  }
}

TEST_F(Cli, OutputFieldNoSolverExportsStopsTheRunBeforeWriting) {
  // Which fields exist is known once the solvers have created theirs: the run checks the names
  // after preparing the world and before writing anything but the output directory.
  auto doc = sample();
  doc["output"]["fields"] = {"density", "presure"};
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " -q");
  EXPECT_EQ(r.code, 2) << r.output;
  for (const char* s : {"/output/fields/1", "'presure'", "did you mean 'pressure'",
                        "fields available: density, pressure"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  EXPECT_TRUE(fs::is_directory(out));
  EXPECT_TRUE(fs::is_empty(out)) << "nothing but the directory is written";
}

TEST_F(Cli, ValidateChecksOutputFieldsAsRunDoes) {
  // validate used to pass a misspelt field that run then refused.
  auto doc = sample();
  doc["output"]["fields"] = {"densty"};
  expect_rejected(doc, {"/output/fields/0", "'densty'", "did you mean 'density'"});
  doc["output"]["fields"] = {"density", "pressure"};
  const Result ok = run_upf("validate " + write(doc));
  EXPECT_EQ(ok.code, 0) << ok.output;
}

TEST_F(Cli, OutputFieldsMustBeNames) {
  auto doc = sample();
  doc["output"]["fields"] = {"density", 3, ""};
  expect_rejected(doc, {"/output/fields/1", "expected a field name, found a number",
                        "/output/fields/2", "found an empty string"});
}

TEST_F(Cli, InstabilityExitsThreeAfterWritingLastGoodFrame) {
  auto doc = sample();
  doc["stability"]["max_speed"] = 0.5;  // the falling column exceeds it within ~0.05 s
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " -q");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("particle id"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("speed"), std::string::npos) << r.output;
  std::ifstream summary(out / "summary.json");
  const auto s = nlohmann::json::parse(summary);
  EXPECT_EQ(s["status"], "unstable");
  EXPECT_TRUE(fs::exists(out / "frames/frame_00001.vtp")) << "the last good frame";
}

TEST_F(Cli, InfoListsSolverParametersWithUnitsAndRanges) {
  const Result r = run_upf("info");
  EXPECT_EQ(r.code, 0);
  for (const char* s : {"pcisph", "eta", "liquid", "frozen", "kg/m^3", "range"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s;
}

}  // namespace
