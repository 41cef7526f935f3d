// `upf compare` as a user meets it: one run per registered liquid solver on a small dam break,
// one report row each, plots of the stated pixel size that are not blank; unstable solvers get
// their row; a bad solver list stops before anything runs; missing plots keep the tables.
#include <sstream>

#include "framework/compare/python_runner.h"
#include "framework/solver/registry.h"
#include "solvers/register_builtin_solvers.h"
#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

// Every liquid solver `upf` is built with: covers each new solver once it is registered.
std::vector<std::string> liquid_solvers() {
  upf::Registry registry;
  upf::register_builtins(registry);
  std::vector<std::string> names;
  for (const auto& s : registry.solvers())
    if (s.type == upf::ParticleType::Liquid) names.push_back(s.name);
  return names;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// Runs use one thread: on a shared machine, two OpenMP threads can spend most of their time
// waiting for each other.
class Compare : public Cli {
 protected:
  // About 1,500 liquid and 5,000 wall particles.
  std::string small_scene(double end) {
    auto doc = sample();
    doc["time"]["end"] = end;
    return write(doc);
  }
  fs::path out() const { return dir_ / "out"; }
};

TEST_F(Compare, EverySolverGetsARowAReportAndPlots) {
  const auto solvers = liquid_solvers();
  ASSERT_FALSE(solvers.empty());
  const Result r = run_upf("compare " + small_scene(0.2) + " --solvers " + join(solvers) +
                           " --out " + out().string() + " --threads 1 -q");
  ASSERT_EQ(r.code, 0) << r.output;

  const std::string md = read_text(out() / "report.md");
  const auto report = read_json(out() / "report.json");
  ASSERT_EQ(report["rows"].size(), solvers.size());
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const std::string& s = solvers[i];
    EXPECT_EQ(count(md, "\n| " + s + " | completed |"), 1u) << s << "\n" << md;
    EXPECT_NE(r.output.find(s), std::string::npos) << "the table on stdout names " << s;
    EXPECT_EQ(report["rows"][i]["solver"], s);
    EXPECT_EQ(report["rows"][i]["status"], "completed");
    for (const char* f : {"particles.pvd", "metrics.csv", "probes.csv", "summary.json"})
      EXPECT_TRUE(fs::exists(out() / s / f)) << s << "/" << f;
  }
  EXPECT_EQ(report["threads"], 1);
  EXPECT_GT(report["particles"]["liquid"].get<int>(), 0);
  EXPECT_TRUE(fs::exists(out() / "report.html"));
  EXPECT_NE(read_text(out() / "report.html").find("<img src=\"density_error.png\""),
            std::string::npos);

  // The plots: the size the docs state, decoded by Python, and not blank.
  const auto& plots = report["plots"];
  EXPECT_EQ(plots["status"], "drawn");
  EXPECT_EQ(plots["width_px"], 1200);
  EXPECT_EQ(plots["height_px"], 700);
  std::vector<std::string> args = {"1200", "700"};
  for (const auto& p : plots["files"])
    args.push_back((out() / p["file"].get<std::string>()).string());
  EXPECT_EQ(args.size(), 2 + 3 + sample()["probes"].size())
      << "density error, dt, accuracy against cost, each probe";
  const fs::path log = dir_ / "check_png.log";
  const auto check = upf::run_python_script(
      fs::path(UPF_SOURCE_DIR) / "tests" / "cli" / "check_png.py", args, log);
  EXPECT_TRUE(check.ok) << check.error << "\n" << read_text(log);
}

TEST_F(Compare, UnstableSolversGetARowWithTheFailure) {
  auto doc = sample();
  doc["time"]["end"] = 0.2;
  doc["stability"]["max_speed"] = 0.5;  // the falling column exceeds it within ~0.05 s
  const auto solvers = liquid_solvers();
  const Result r = run_upf("compare " + write(doc) + " --solvers " + join(solvers) + " --out " +
                           out().string() + " --no-frames --threads 1 -q");
  ASSERT_EQ(r.code, 0) << "an instability is a result of the comparison\n" << r.output;
  const auto report = read_json(out() / "report.json");
  ASSERT_EQ(report["rows"].size(), solvers.size());
  for (const auto& row : report["rows"]) {
    EXPECT_EQ(row["status"], "unstable");
    EXPECT_NE(row["failure"].get<std::string>().find("speed"), std::string::npos);
    const double t = row["failure_time_s"].get<double>();
    EXPECT_GT(t, 0);
    EXPECT_LT(t, 0.2);
  }
  const std::string md = read_text(out() / "report.md");
  EXPECT_EQ(count(md, " | unstable at t = "), solvers.size()) << md;
  EXPECT_NE(md.find("## Failures"), std::string::npos);
}

TEST_F(Compare, BadSolverListsAreRejectedBeforeAnythingRuns) {
  const std::string scene = small_scene(0.2);
  const std::string first = liquid_solvers().front();
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"pcisp", {"unknown solver 'pcisp'", "did you mean 'pcisph'", "registered solvers: "}},
      {first + ",nope", {"unknown solver 'nope'"}},
      {first + "," + first, {"'" + first + "' is listed twice"}},
      {"''", {"empty solver name"}},
      {",", {"--solvers"}},
  };
  for (const auto& [list, needles] : cases) {
    const Result r =
        run_upf("compare " + scene + " --solvers " + list + " --out " + out().string() + " -q");
    EXPECT_EQ(r.code, 2) << list << "\n" << r.output;
    for (const auto& n : needles) EXPECT_NE(r.output.find(n), std::string::npos) << n << r.output;
    EXPECT_FALSE(fs::exists(out())) << list << ": nothing may run";
  }
}

TEST_F(Compare, MissingPlotsKeepTheTablesAndExitOne) {
  const fs::path broken = dir_ / "broken.py";
  std::ofstream(broken) << "raise SystemExit('broken on purpose')\n";
  const std::string base = "compare " + small_scene(0.02) + " --out " + out().string() +
                           " --no-frames --threads 1 -q --solvers " + liquid_solvers().front();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {base + " --plot-script " + (dir_ / "nope.py").string(), "not found"},
      {base + " --plot-script " + broken.string(), "broken on purpose"},
  };
  for (const auto& [args, why] : cases) {
    const Result r = run_upf(args);
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("the plots are missing"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
    EXPECT_NE(read_text(out() / "report.md").find("The plots are missing"), std::string::npos);
    EXPECT_NE(read_text(out() / "report.md").find("| completed |"), std::string::npos);
    EXPECT_TRUE(fs::exists(out() / "report.html"));
    EXPECT_EQ(read_json(out() / "report.json")["plots"]["status"], "missing");
  }
  const Result r = run_upf(base, "UPF_PYTHON=/nonexistent/python3");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot start /nonexistent/python3"), std::string::npos) << r.output;
}

}  // namespace

namespace {

// report.json without what differs from one process to the next: timings and the date.
nlohmann::json without_timings(nlohmann::json report) {
  report.erase("date");
  report.erase("plots");
  for (auto& row : report["rows"])
    for (const char* key : {"wall_time_s", "fluid_particle_steps_per_second",
                            "wall_seconds_per_simulated_second", "threads", "mean_threads"})
      row.erase(key);
  report.erase("threads");
  return report;
}

// Split over processes, as a Slurm job array runs it: the plan, its tasks in any order (here
// last first, one at two threads), then the report: the same figures as one `upf compare`.
TEST_F(Compare, APlannedComparisonRunAsTasksGivesTheSameReport) {
  const std::string scene = small_scene(0.05);
  const std::string solvers = " --solvers pcisph,wcsph --no-frames -q";
  const fs::path split = dir_ / "split";
  const Result whole =
      run_upf("compare " + scene + solvers + " --threads 1 --out " + out().string());
  ASSERT_EQ(whole.code, 0) << whole.output;

  const Result plan =
      run_upf("compare " + scene + solvers + " --threads 1 --plan --out " + split.string());
  ASSERT_EQ(plan.code, 0) << plan.output;
  EXPECT_NE(plan.output.find("planned 2 runs"), std::string::npos) << plan.output;
  EXPECT_NE(plan.output.find("sbatch --array=0-1"), std::string::npos) << plan.output;
  EXPECT_FALSE(fs::exists(split / "pcisph")) << "--plan runs nothing";

  // Collecting before every task has run names what is missing.
  const Result early = run_upf("compare --collect --out " + split.string());
  EXPECT_EQ(early.code, 2) << early.output;
  EXPECT_NE(early.output.find("(task 0)"), std::string::npos) << early.output;
  EXPECT_NE(early.output.find("(task 1)"), std::string::npos) << early.output;

  const Result t1 = run_upf("compare --task 1 -q --threads 2 --out " + split.string());
  ASSERT_EQ(t1.code, 0) << t1.output;
  const Result t0 = run_upf("compare --task 0 -q --out " + split.string());
  ASSERT_EQ(t0.code, 0) << t0.output;
  const Result collected = run_upf("compare --collect --out " + split.string());
  ASSERT_EQ(collected.code, 0) << collected.output;

  const auto a = read_json(out() / "report.json"), b = read_json(split / "report.json");
  EXPECT_EQ(without_timings(a), without_timings(b));
  EXPECT_EQ(b["rows"][0]["solver"], "pcisph");
  EXPECT_EQ(b["rows"][1]["solver"], "wcsph");
  EXPECT_EQ(read_text(out() / "pcisph" / "probes.csv"), read_text(split / "pcisph" / "probes.csv"));
  EXPECT_EQ(read_text(out() / "wcsph" / "probes.csv"), read_text(split / "wcsph" / "probes.csv"));
}

TEST_F(Compare, SplitComparisonsRefuseBadTasksAndMixedOptions) {
  const std::string scene = small_scene(0.05);
  const fs::path split = dir_ / "split";
  const std::vector<std::pair<std::string, std::string>> before_plan = {
      {"compare --task 0 --out " + split.string(), "no comparison planned here"},
      {"compare --collect --out " + split.string(), "no comparison planned here"},
      {"compare --out " + split.string(), "give a scene file"},
  };
  for (const auto& [args, needle] : before_plan) {
    const Result r = run_upf(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << args << "\n" << r.output;
  }
  ASSERT_EQ(
      run_upf("compare " + scene + " --solvers pcisph --plan -q --out " + split.string()).code, 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"compare --task 3 --out " + split.string(), "task 3 is outside the plan's 1 runs (0..0)"},
      {"compare --task 0 --plan --out " + split.string(),
       "give one of --plan, --task and --collect"},
      {"compare " + scene + " --task 0 --out " + split.string(), "the scene comes from the plan"},
      {"compare --collect --end 1 --out " + split.string(), "--end comes from the plan"},
  };
  for (const auto& [args, needle] : cases) {
    const Result r = run_upf(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << args << "\n" << r.output;
  }
  std::ofstream(split / "plan.json") << "{ broken";
  const Result broken = run_upf("compare --task 0 --out " + split.string());
  EXPECT_EQ(broken.code, 2) << broken.output;
  EXPECT_NE(broken.output.find("plan.json: not valid JSON"), std::string::npos) << broken.output;
}

}  // namespace

namespace {

// A parameter sweep: --vary runs the solver at each value, one named row and directory each; a
// tighter eta gives a smaller compression, and more steps (PCISPH's resting-compression limit
// shortens them). Split over tasks it gives the same rows.
TEST_F(Compare, VaryRunsASweepWithANamedRowPerValue) {
  const std::string scene = small_scene(0.05);
  const std::string sweep =
      " --solvers pcisph --vary /materials/water/solver/eta=0.01,0.001 --no-frames -q";
  const Result r = run_upf("compare " + scene + sweep + " --threads 1 --out " + out().string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto report = read_json(out() / "report.json");
  ASSERT_EQ(report["rows"].size(), 2u);
  EXPECT_EQ(report["rows"][0]["run"], "pcisph,eta=0.01");
  EXPECT_EQ(report["rows"][1]["run"], "pcisph,eta=0.001");
  EXPECT_EQ(report["rows"][1]["solver"], "pcisph");
  EXPECT_TRUE(fs::exists(out() / "pcisph,eta=0.001" / "summary.json"));
  EXPECT_GT(report["rows"][1]["steps"].get<int>(), report["rows"][0]["steps"].get<int>());
  EXPECT_LT(report["rows"][1]["mean_avg_density_error"].get<double>(),
            report["rows"][0]["mean_avg_density_error"].get<double>());
  EXPECT_NE(read_text(out() / "report.md").find("| pcisph,eta=0.001 | completed |"),
            std::string::npos);

  const fs::path split = dir_ / "split";
  const Result plan =
      run_upf("compare " + scene + sweep + " --threads 1 --plan --out " + split.string());
  ASSERT_EQ(plan.code, 0) << plan.output;
  EXPECT_NE(plan.output.find("0 pcisph,eta=0.01 1 pcisph,eta=0.001"), std::string::npos)
      << plan.output;
  for (const char* k : {"1", "0"})
    ASSERT_EQ(run_upf("compare -q --task " + std::string(k) + " --out " + split.string()).code, 0);
  ASSERT_EQ(run_upf("compare --collect --out " + split.string()).code, 0);
  EXPECT_EQ(without_timings(report), without_timings(read_json(split / "report.json")));

  const Result bad = run_upf("compare " + scene + " --vary /time/end --out " + out().string());
  EXPECT_EQ(bad.code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--vary /time/end"), std::string::npos) << bad.output;
}

}  // namespace

namespace {

// Every run of a sweep has a folder of its own, named after its values: values that would run
// twice or share a folder, and a pointer varied twice (the later overwriting the earlier while
// the rows are named after both), stop the command before anything runs.
TEST_F(Compare, VaryRefusesValuesAndPointersThatWouldMixRuns) {
  const std::string scene = small_scene(0.02);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"--vary /time/end=0.02,0.02", {"--vary /time/end=0.02,0.02", "'0.02' is given twice"}},
      {"--vary /time/end=0.02,2e-2", {"'0.02' and '2e-2' set the same value"}},
      {"--vary /description=a/b,a_b",
       {"--vary /description=a/b,a_b", "'a/b' and 'a_b' both become 'a_b'"}},
      {"--vary /time/end=0.02 --vary /time/end=0.01",
       {"--vary /time/end=0.02 and --vary /time/end=0.01", "both set /time/end"}},
      {"--vary /time/end=0.02,0.01 --vary '/time={\"end\":0.03}'",
       {"the later replaces /time, which holds /time/end"}},
  };
  for (const auto& [vary, needles] : cases) {
    const Result r = run_upf("compare " + scene + " --solvers pcisph --no-frames -q " + vary +
                             " --out " + out().string());
    EXPECT_EQ(r.code, 2) << vary << "\n" << r.output;
    for (const auto& n : needles) EXPECT_NE(r.output.find(n), std::string::npos) << n << r.output;
    EXPECT_FALSE(fs::exists(out())) << vary << ": nothing may run";
  }
}

// plan.json may be edited by hand: a run name that is a path would send a task's files outside
// OUT, and two equal names would share a folder. Every task and the collect refuse such a plan.
TEST_F(Compare, PlannedRunNamesMustBePlainAndUnique) {
  const fs::path split = dir_ / "split";
  ASSERT_EQ(run_upf("compare " + small_scene(0.01) +
                    " --solvers pcisph,wcsph --no-frames -q --plan --out " + split.string())
                .code,
            0);
  const auto plan = read_json(split / "plan.json");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"../escaped", "plan.json:/runs/1/name: '../escaped' holds a path separator"},
      {(dir_ / "absolute").string(), "plan.json:/runs/1/name: '" + (dir_ / "absolute").string()},
      {"..", "plan.json:/runs/1/name: '..' is '..'"},
      {"pcisph", "plan.json:/runs/1/name: 'pcisph' is also the name of run 0"},
  };
  for (const auto& [name, needle] : cases) {
    auto edited = plan;
    edited["runs"][1]["name"] = name;
    std::ofstream(split / "plan.json") << edited.dump(2);
    for (const std::string mode : {"--task 1", "--task 0", "--collect"}) {
      const Result r = run_upf("compare -q " + mode + " --out " + split.string());
      EXPECT_EQ(r.code, 2) << name << " " << mode << "\n" << r.output;
      EXPECT_NE(r.output.find(needle), std::string::npos) << needle << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(dir_ / "escaped"));
    EXPECT_FALSE(fs::exists(dir_ / "absolute"));
    EXPECT_FALSE(fs::exists(split / "pcisph")) << "no task may run";
  }
}

}  // namespace
