// Several liquids in one scene (docs/multiphase.md): what cannot be simulated correctly is refused
// before anything runs (exit 2), naming both materials: liquids of different solvers, a density
// ratio above 10, and different densities under a solver without the density-contrast forms.
#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

nlohmann::json with_oil(nlohmann::json doc, double density, const std::string& solver) {
  doc["materials"]["oil"] = {
      {"type", "liquid"}, {"density", density}, {"solver", {{"name", solver}}}};
  return doc;
}

TEST_F(Cli, LiquidsOfDifferentSolversAreRefused) {
  auto doc = with_oil(sample(), 800, "dfsph");
  expect_rejected(doc, {"/materials/", "'dfsph'", "'pcisph'", "one pressure solve"});
}

TEST_F(Cli, ADensityRatioAboveTenIsRefused) {
  auto doc = sample();
  doc = with_oil(doc, 50, doc["materials"]["water"]["solver"]["name"]);
  doc["materials"]["oil"]["solver"] = doc["materials"]["water"]["solver"];
  expect_rejected(doc, {"/materials/", "/density", "'oil' (50 kg/m^3)", "'water' (1000 kg/m^3)",
                        "ratio of 20", "above 10"});
}

TEST_F(Cli, DifferentDensitiesUnderSphAreRefused) {
  auto doc = sample();
  doc["materials"]["water"]["solver"] = {{"name", "sph"}};
  doc = with_oil(doc, 800, "sph");
  expect_rejected(doc, {"/solver", "solver 'sph'", "'oil' (800 kg/m^3)", "pcisph"});
}

TEST_F(Cli, InfoSaysWhichSolversHoldLiquidsOfDifferentDensity) {
  const Result r = run_upf("info");
  EXPECT_EQ(r.code, 0);
  const auto pcisph = r.output.find("  pcisph (for liquid materials)");
  const auto sph = r.output.find("  sph (for liquid materials)");
  ASSERT_NE(pcisph, std::string::npos) << r.output;
  ASSERT_NE(sph, std::string::npos) << r.output;
  const std::string line = "liquids of different density: ";
  EXPECT_EQ(r.output.compare(r.output.find(line, pcisph) + line.size(), 3, "yes"), 0);
  EXPECT_EQ(r.output.compare(r.output.find(line, sph) + line.size(), 2, "no"), 0);
}

}  // namespace
