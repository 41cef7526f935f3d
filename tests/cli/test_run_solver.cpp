// `upf run --solver NAME`: the named solver moves the scene's liquids, with the scene's parameters
// when the scene names it and its defaults otherwise; an unknown name is bad input.
#include "framework/solver/registry.h"
#include "solvers/register_builtin_solvers.h"
#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

TEST_F(Cli, RunSolverUnknownNameListsTheRegisteredOnes) {
  const Result r =
      run_upf("run " + write(sample()) + " --solver pcisp -q --out " + (dir_ / "out").string());
  EXPECT_EQ(r.code, 2) << r.output;
  for (const char* s : {"--solver", "unknown solver 'pcisp'", "did you mean 'pcisph'",
                        "registered solvers: ", "pcisph"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(Cli, RunSolverMovesTheLiquidsWithTheSceneOrDefaultParameters) {
  upf::Registry registry;
  upf::register_builtins(registry);
  auto doc = sample();
  doc["materials"]["water"]["solver"] = {{"name", "pcisph"}, {"eta", 0.02}};
  const std::string scene = write(doc);
  for (const auto& solver : registry.solvers()) {
    if (solver.type != upf::ParticleType::Liquid) continue;
    const fs::path out = dir_ / solver.name;
    const Result r = run_upf("run " + scene + " --solver " + solver.name +
                             " --end 0.01 --threads 1 -q " + "--no-frames --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream in(out / "summary.json");
    const auto materials = nlohmann::json::parse(in)["materials"];
    EXPECT_EQ(materials["water"]["solver"], solver.name);
    EXPECT_TRUE(materials["walls"]["solver"].is_null());
    const auto& params = materials["water"]["solver_params"];
    for (const auto& spec : solver.params) {
      const double expected =
          solver.name == "pcisph" && spec.name == "eta" ? 0.02 : spec.default_value;
      EXPECT_DOUBLE_EQ(params[spec.name].get<double>(), expected)
          << solver.name << " " << spec.name;
    }
  }
}

}  // namespace
