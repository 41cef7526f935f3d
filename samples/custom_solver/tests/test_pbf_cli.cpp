// The PBF sample as a user meets it: `upf` lists the solver registered from samples/custom_solver
// with its parameters, runs the sample scene, and writes the solver's own exported fields, which
// output.fields may name like any built-in field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using upf::cli_test::run_upf;

class PbfCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("upf_pbf_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path sample() const {
    return fs::path(UPF_SOURCE_DIR) / "samples" / "custom_solver" / "pbf_dam_break.json";
  }
  fs::path dir_;
};

TEST_F(PbfCli, InfoListsPbfWithItsParameters) {
  const auto r = run_upf("info");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* s : {"pbf (for liquid materials)", "Macklin", "iterations", "relaxation",
                        "tensile_k", "xsph", "vorticity", "m/s"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s;
}

TEST_F(PbfCli, RunsTheSampleSceneAndWritesItsFields) {
  const fs::path out = dir_ / "out";
  const auto r =
      run_upf("run " + sample().string() + " --end 0.2 --out " + out.string() + " --threads 2 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream summary_file(out / "summary.json");
  const auto summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_NEAR(summary["simulated_time_s"].get<double>(), 0.2, 1e-9);
  // PBF ran: its stages and its fixed iteration count are in the summary (and, where the summary
  // names each material's solver, that name).
  EXPECT_TRUE(summary["median_stage_ms"].contains("constraints")) << summary.dump(2);
  EXPECT_EQ(summary["max_pressure_iterations"], 4);
  if (summary.contains("materials")) {
    EXPECT_EQ(summary["materials"]["water"]["solver"], "pbf");
  }
  // The last frame carries the solver's own field next to the shared ones.
  std::ifstream frame(out / "frames" / "frame_00006.vtp", std::ios::binary);
  std::stringstream text;
  text << frame.rdbuf();
  for (const char* s : {"Name=\"density\"", "Name=\"pressure\"", "Name=\"pbf.lambda\""})
    EXPECT_NE(text.str().find(s), std::string::npos) << s;
}

TEST_F(PbfCli, MisspeltSolverFieldIsNamedWithTheFieldsThereAre) {
  std::ifstream in(sample());
  auto doc = nlohmann::json::parse(in);
  doc["output"]["fields"] = {"pbf.lambdas"};
  const fs::path scene = dir_ / "scene.json";
  std::ofstream(scene) << doc.dump(2);
  const auto r = run_upf("run " + scene.string() + " --out " + (dir_ / "out").string() + " -q");
  EXPECT_EQ(r.code, 2) << r.output;
  for (const char* s :
       {"/output/fields/0", "did you mean 'pbf.lambda'", "density, pbf.lambda, pressure"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
}

}  // namespace
