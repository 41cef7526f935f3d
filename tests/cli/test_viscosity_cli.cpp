// The implicit viscosity's input and failure (docs/viscosity.md): bad values are refused before
// anything runs (exit 2, the JSON path and range); a solve that does not converge within its cap
// stops the run with exit 3, names the step, the residual and the cap, and keeps the last good
// frame.
#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

TEST_F(Cli, ImplicitViscosityIsAWholeNumberFlag) {
  auto doc = sample();
  doc["materials"]["water"]["implicit_viscosity"] = 2;
  expect_rejected(doc, {"/materials/water/implicit_viscosity", "out of range", "[0, 1]"});
  doc["materials"]["water"]["implicit_viscosity"] = 0.5;
  expect_rejected(doc, {"/materials/water/implicit_viscosity", "whole number"});
  doc["materials"]["water"]["implicit_viscosity"] = 1;
  doc["materials"]["water"]["viscosity_tolerance"] = 0;
  expect_rejected(doc, {"/materials/water/viscosity_tolerance", "out of range"});
}

TEST_F(Cli, LiquidsOfOneSolverMustAgreeOnImplicitViscosity) {
  auto doc = sample();
  doc["materials"]["honey"] = {{"type", "liquid"},
                               {"density", 1400},
                               {"viscosity", 0.1},
                               {"implicit_viscosity", 1},
                               {"solver", {{"name", "pcisph"}, {"eta", 0.01}}}};
  expect_rejected(doc, {"/materials/water/implicit_viscosity", "'honey'", "one viscous solve"});
}

TEST_F(Cli, ImplicitViscosityThatDoesNotConvergeExitsThreeWithTheLastGoodFrame) {
  auto doc = sample();
  auto& water = doc["materials"]["water"];
  water["viscosity"] = 1.0;
  water["boundary_viscosity"] = 1.0;
  water["implicit_viscosity"] = 1;
  water["viscosity_tolerance"] = 1e-8;
  water["viscosity_max_iterations"] = 1;
  const fs::path out = dir_ / "out";
  const Result r = run_upf("run " + write(doc) + " --out " + out.string() + " -q");
  EXPECT_EQ(r.code, 3) << r.output;
  for (const char* s : {"unstable at step 0", "implicit viscosity did not converge",
                        "relative residual", "viscosity_max_iterations 1"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  std::ifstream summary(out / "summary.json");
  const auto s = nlohmann::json::parse(summary);
  EXPECT_EQ(s["status"], "unstable");
  EXPECT_TRUE(fs::exists(out / "frames/frame_00000.vtp")) << "the last good frame";
}

}  // namespace
