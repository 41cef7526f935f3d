// The comparison library: --solver overrides, the checked solver list, a comparison in which one
// solver goes unstable while another completes, and reports that survive NaN probes and missing
// plots. A test solver that accelerates its particles without bound provides the instability.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "framework/compare/compare_plan.h"
#include "framework/compare/compare_report.h"
#include "framework/compare/comparison.h"
#include "framework/compare/report_table.h"
#include "framework/scene/solver_override.h"
#include "framework/world/world.h"
#include "tests/physics/scene_helpers.h"

namespace upf {
namespace {

namespace fs = std::filesystem;

// Accelerates its particles downwards, ignoring walls, until the world stops the run.
class RunawaySolver : public Solver {
 public:
  RunawaySolver(const ParamValues& params, std::vector<MaterialId> materials)
      : acceleration_(Real(params.get("acceleration"))), materials_(std::move(materials)) {}
  std::string_view name() const override { return "runaway"; }
  // Exports the fields every fluid solver exports, which the sample scene asks for.
  void prepare(World& world) override {
    world.particles().scalar_field("density", 0, true);
    world.particles().scalar_field("pressure", 0, true);
  }
  Real max_time_step(const World&) const override { return Real(1); }
  std::vector<std::string> stages() const override { return {}; }
  void step(World& world, Real dt, StageRunner&) override {
    Particles& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (std::find(materials_.begin(), materials_.end(), p.material[i]) == materials_.end())
        continue;
      p.velocity[i].y -= acceleration_ * dt;
      p.position[i] += p.velocity[i] * dt;
    }
  }
  SolverStats stats() const override { return {}; }

 private:
  Real acceleration_;
  std::vector<MaterialId> materials_;
};

SolverInfo runaway_info(const std::string& name, ParticleType type) {
  return {name,
          type,
          "test solver: unbounded acceleration",
          "none",
          {{"acceleration", "m/s^2", 5000, 0, 1e9, "downward acceleration"}},
          [](const ParamValues& values, std::vector<MaterialId> materials) {
            return std::make_unique<RunawaySolver>(values, std::move(materials));
          },
          {}};
}

class CompareLibrary : public ::testing::Test {
 protected:
  CompareLibrary() {
    registry_.add_solver(runaway_info("runaway", ParticleType::Liquid));
    registry_.add_solver(runaway_info("sand_test", ParticleType::Granular));
  }
  SceneDescription scene(double end = 0.05) const {
    auto doc = testing::load_sample_json("dam_break.json");
    doc["particle_spacing"] = 0.05;
    doc["time"]["end"] = end;
    doc["materials"]["water"]["solver"] = {{"name", "pcisph"}, {"eta", 0.02}};
    return read_scene(doc, registry_, "test");
  }
  static const Material& material(const SceneDescription& s, const std::string& name) {
    for (const auto& m : s.materials)
      if (m.name == name) return m;
    throw std::out_of_range(name);
  }
  static std::string problems(const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  Registry registry_ = testing::builtin_registry();
};

TEST_F(CompareLibrary, WithSolverMovesTheLiquidsWithDefaultParameters) {
  const SceneDescription s = with_solver(scene(), registry_, "runaway");
  EXPECT_EQ(material(s, "water").solver, "runaway");
  EXPECT_EQ(material(s, "water").solver_params.get("acceleration"), 5000);
  EXPECT_TRUE(material(s, "walls").solver.empty()) << "frozen walls are not liquid";
}

TEST_F(CompareLibrary, WithSolverKeepsTheScenesParametersForAllItsMaterials) {
  SceneDescription base = scene();
  Material second = material(base, "water");
  second.name = "oil";
  second.solver = "runaway";
  second.solver_params = ParamValues(registry_.find_solver("runaway")->params);
  base.materials.push_back(second);
  const SceneDescription s = with_solver(base, registry_, "pcisph");
  for (const char* m : {"water", "oil"}) {
    EXPECT_EQ(material(s, m).solver, "pcisph") << m;
    EXPECT_DOUBLE_EQ(material(s, m).solver_params.get("eta"), 0.02) << m;
  }
}

TEST_F(CompareLibrary, WithSolverRejectsUnknownAndUnmatchedSolvers) {
  const std::string unknown = problems([&] { with_solver(scene(), registry_, "runawya"); });
  EXPECT_NE(unknown.find("--solver: unknown solver 'runawya' (did you mean 'runaway'?)"),
            std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find("registered solvers: pcisph"), std::string::npos) << unknown;
  const std::string unmatched = problems([&] { with_solver(scene(), registry_, "sand_test"); });
  EXPECT_NE(unmatched.find("'sand_test' moves granular particles"), std::string::npos) << unmatched;
  EXPECT_NE(unmatched.find("no granular material"), std::string::npos) << unmatched;
  std::size_t liquid_solvers = 0;
  for (const auto& info : registry_.solvers()) liquid_solvers += info.type == ParticleType::Liquid;
  EXPECT_EQ(solvers_for_scene(scene(), registry_).size(), liquid_solvers)
      << "every liquid solver, not the granular ones";
  EXPECT_LT(liquid_solvers, registry_.solvers().size());
}

TEST_F(CompareLibrary, PlanReportsEveryProblemAtOnce) {
  const std::string all = problems([&] {
    plan_comparison(scene(), registry_, {"pcisph", "", "nope", "pcisph", "sand_test"});
  });
  for (const char* s : {"empty solver name at position 2", "unknown solver 'nope'",
                        "'pcisph' is listed twice", "'sand_test' moves granular particles"})
    EXPECT_NE(all.find(s), std::string::npos) << s << "\n" << all;
  EXPECT_NE(problems([&] { plan_comparison(scene(), registry_, {}); }).find("no solver given"),
            std::string::npos);
  EXPECT_EQ(plan_comparison(scene(), registry_, {"runaway", "pcisph"}).size(), 2u);
}

TEST_F(CompareLibrary, AnUnstableSolverGetsItsRowAndTheOthersComplete) {
  const fs::path out = fs::temp_directory_path() / "upf_unit_compare_unstable";
  fs::remove_all(out);
  CompareOptions options;
  options.out_dir = out;
  options.threads = 1;  // the machine may be shared: 2 threads can wait on each other
  options.write_frames = false;
  const auto plan = plan_comparison(scene(0.1), registry_, {"runaway", "pcisph"});
  const Comparison c = run_comparison(plan, registry_, options);

  ASSERT_EQ(c.rows.size(), 2u);
  const CompareRow& runaway = c.rows[0];
  EXPECT_TRUE(runaway.unstable());
  EXPECT_NE(runaway.result.failure.find("speed"), std::string::npos) << runaway.result.failure;
  // 5000 m/s^2 passes the default 100 m/s limit at t = 0.02 s.
  EXPECT_NEAR(runaway.result.simulated_time, 0.02, 0.005);
  EXPECT_EQ(status_text(runaway).rfind("unstable at t = 0.02", 0), 0u) << status_text(runaway);
  EXPECT_EQ(c.rows[1].result.status, "completed");
  EXPECT_NEAR(c.rows[1].result.simulated_time, 0.1, 1e-9);
  EXPECT_EQ(c.threads, 1);
  EXPECT_GT(c.liquid_particles, 0u);
  for (const char* s : {"runaway", "pcisph"}) EXPECT_TRUE(fs::exists(out / s / "summary.json"));

  // The reports: written without plots (no script here), NaN probes as n/a and null.
  const PlotOutcome plots = write_compare_report(c, out, out / "no_such_script.py");
  EXPECT_FALSE(plots.ok);
  std::ifstream md_in(out / "report.md");
  std::stringstream md;
  md << md_in.rdbuf();
  EXPECT_NE(md.str().find("| runaway | unstable at t = "), std::string::npos) << md.str();
  EXPECT_NE(md.str().find("| pcisph | completed |"), std::string::npos) << md.str();
  EXPECT_NE(md.str().find("## Failures"), std::string::npos);
  EXPECT_NE(md.str().find("The plots are missing: plot script"), std::string::npos);
  std::ifstream json_in(out / "report.json");
  const auto report = nlohmann::json::parse(json_in);
  EXPECT_EQ(report["rows"][0]["status"], "unstable");
  EXPECT_NEAR(report["rows"][0]["failure_time_s"].get<double>(), 0.02, 0.005);
  EXPECT_TRUE(report["rows"][1]["failure"].is_null());
  EXPECT_TRUE(report["rows"][1]["final_probes"]["pressure_far_wall_bottom"].is_null())
      << "no liquid reaches the far wall by 0.1 s: NaN";
  EXPECT_EQ(report["plots"]["status"], "missing");
  EXPECT_TRUE(fs::exists(out / "report.html"));
  // Probes carry their units: the table's column, report.json and the plot's axis label.
  EXPECT_NE(md.str().find("pressure_far_wall_bottom [Pa]"), std::string::npos) << md.str();
  const auto& probes = report["probes"];
  const auto& units = report["probe_units"];
  ASSERT_EQ(probes.size(), units.size());
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const std::string name = probes[i];
    EXPECT_EQ(units[i], name.rfind("pressure", 0) == 0 ? "Pa" : "m") << name;
  }
  bool labelled = false;
  for (const auto& f : report["plots"]["files"])
    if (f["kind"] == "probe" && f["probe"] == "pressure_far_wall_bottom")
      labelled = f["label"] == "pressure_far_wall_bottom [Pa]";
  EXPECT_TRUE(labelled) << report["plots"].dump();
  fs::remove_all(out);
}

TEST(ReportTable, NonFiniteNumbersAndAlignment) {
  EXPECT_EQ(format_number(std::nan("")), "n/a");
  EXPECT_EQ(format_number(INFINITY), "n/a");
  EXPECT_EQ(format_number(0.001234567), "0.001235");
  const std::string text = format_text_table({{"a", "bbb"}, {{"long", "c"}}});
  EXPECT_EQ(text, "a     bbb\n----  ---\nlong  c\n");
}

}  // namespace
}  // namespace upf
