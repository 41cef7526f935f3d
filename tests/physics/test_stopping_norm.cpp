// The stopping tests of the iterative fluid solvers (compression_stats.h, StoppingError): the
// papers bound the average compression (Solenthaler & Pajarola 2009, Ihmsen et al. 2014, Bender
// & Koschier 2017), which lets single particles stay far compressed; `stop_percentile: 100`
// bounds the largest. Checked on the first 0.6 s of a coarse dam break (4 cm), through the
// collapse and the impact on the far wall.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf {
namespace {

struct Bounds {
  int steps = 0;
  int over_eta = 0;    // steps whose largest predicted compression exceeded eta
  int at_maximum = 0;  // steps that stopped at max_iterations
  double mean_iterations = 0;
};

Bounds run(const std::string& solver, double eta, double percentile) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  doc["materials"]["water"]["solver"] = {
      {"name", solver}, {"eta", eta}, {"stop_percentile", percentile}, {"max_iterations", 200}};
  testing::TestWorld tw(doc, 2);
  World& w = *tw.world;
  Bounds b;
  while (w.time() < 0.6 - 1e-12) {
    w.step(w.next_time_step_until(0.6));
    const SolverStats& s = w.last_step().solver;
    ++b.steps;
    b.mean_iterations += s.iterations;
    if (s.max_density_error > eta) ++b.over_eta;
    if (s.iterations >= 200) ++b.at_maximum;
  }
  b.mean_iterations /= b.steps;
  std::printf(
      "%s eta %.3g stop_percentile %g: %d steps, mean %.2f iterations, %d over eta, %d at "
      "the maximum\n",
      solver.c_str(), eta, percentile, b.steps, b.mean_iterations, b.over_eta, b.at_maximum);
  return b;
}

// Bounding the largest compression: every step that converged ends with no particle compressed
// by more than eta; bounding the average at the same eta leaves particles above it.
TEST(StoppingNorm, TheLargestCompressionIsBoundedWhenAskedForEverySolver) {
  const std::map<std::string, std::string> paper = {{"pcisph", "Solenthaler & Pajarola 2009"},
                                                    {"dfsph", "Bender & Koschier 2017"},
                                                    {"iisph", "Ihmsen et al. 2014"}};
  for (const std::string solver : {"pcisph", "dfsph", "iisph"}) {
    SCOPED_TRACE(solver);
    const Bounds average = run(solver, 0.01, 0);
    const Bounds largest = run(solver, 0.01, 100);
    testing::record_validation(
        "share of steps with a particle compressed beyond eta, " + solver + " bounding the average",
        paper.at(solver) + ": the average stopping test lets single particles stay compressed",
        "above 0", "above 0", double(average.over_eta) / average.steps);
    EXPECT_GT(average.over_eta, 0) << "the average alone already bounded every particle";
    testing::record_validation("share of steps that converged with a particle beyond eta, " +
                                   solver + " bounding the largest",
                               "stop_percentile 100: no particle beyond eta", "0", "exactly 0",
                               double(largest.over_eta - largest.at_maximum) / largest.steps);
    EXPECT_EQ(largest.over_eta, largest.at_maximum);
    EXPECT_LT(largest.at_maximum, largest.steps / 10);
    EXPECT_GT(largest.mean_iterations, average.mean_iterations);
  }
}

// A percentile lies between: bounding the 99th percentile takes more iterations than bounding
// the average (1 % of the particles above eta is a stricter test than an average below it) and
// fewer than bounding the largest.
TEST(StoppingNorm, APercentileBoundsBetweenTheAverageAndTheLargest) {
  const Bounds average = run("pcisph", 0.01, 0);
  const Bounds p99 = run("pcisph", 0.01, 99);
  const Bounds largest = run("pcisph", 0.01, 100);
  char expected[48];
  std::snprintf(expected, sizeof expected, "between %.2f and %.2f", average.mean_iterations,
                largest.mean_iterations);
  testing::record_validation("mean iterations per step, pcisph bounding the 99th percentile",
                             "between bounding the average and the largest", expected,
                             "strictly between", p99.mean_iterations);
  EXPECT_GT(p99.mean_iterations, average.mean_iterations);
  EXPECT_LT(p99.mean_iterations, largest.mean_iterations);
}

}  // namespace
}  // namespace upf
