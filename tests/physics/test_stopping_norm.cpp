// The stopping tests of the iterative fluid solvers (compression_stats.h, StoppingError): the
// papers bound the average compression (Solenthaler & Pajarola 2009, Ihmsen et al. 2014, Bender
// & Koschier 2017), which lets single particles stay far compressed; `stop_percentile: 100`
// bounds the largest. Checked on the first 0.6 s of a coarse dam break (4 cm), through the
// collapse and the impact on the far wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf {
namespace {

struct Bounds {
  int steps = 0;
  int over_eta = 0;    // steps whose largest predicted compression exceeded eta
  int at_maximum = 0;  // steps that stopped at max_iterations
  double mean_iterations = 0;
  // The largest compression of the density summed at the particles, as each step finds it
  // (the density field after a step: summed at that step's start, where the last one left them).
  double largest_at_particles = 0;
};

Bounds run(const std::string& solver, double eta, double percentile,
           bool summed_density_check = false) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  doc["materials"]["water"]["solver"] = {
      {"name", solver}, {"eta", eta}, {"stop_percentile", percentile}, {"max_iterations", 200}};
  if (summed_density_check) doc["materials"]["water"]["solver"]["summed_density_check"] = 1;
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
    const Particles& p = w.particles();
    const std::vector<Real>& density = p.scalar_fields().at("density").values;
    if (b.steps > 1)
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.type[i] == ParticleType::Liquid)
          b.largest_at_particles = std::max(b.largest_at_particles, double(density[i]) / 1000 - 1);
  }
  b.mean_iterations /= b.steps;
  std::printf(
      "%s eta %.3g stop_percentile %g%s: %d steps, mean %.2f iterations, %d over eta, %d at "
      "the maximum, largest compression at the particles %.4f\n",
      solver.c_str(), eta, percentile, summed_density_check ? " summed check" : "", b.steps,
      b.mean_iterations, b.over_eta, b.at_maximum, b.largest_at_particles);
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

// DFSPH and IISPH bound a density predicted linearly from their velocities; the next step sums
// the density where the particles went and finds more. Checked against the summed density
// (summed_density_check, dfsph_summed_density.h, iisph_solve.h), the solve holds that density
// below eta too, as PCISPH's does.
void expect_summed_check_bounds_the_particles(const std::string& solver, const std::string& paper) {
  const double eta = 0.01;
  const Bounds linear = run(solver, eta, 100);
  const Bounds summed = run(solver, eta, 100, true);
  testing::record_validation(
      "largest compression at the particles, " + solver + " bounding the largest at eta 1 %",
      paper + ": the linear prediction underestimates it", "above eta", "above 3 eta",
      linear.largest_at_particles);
  EXPECT_GT(linear.largest_at_particles, 3 * eta) << "the linear prediction already bounds it";
  testing::record_validation(
      "largest compression at the particles, " + solver + " with summed_density_check at eta 1 %",
      "summed at x + dt v (as PCISPH, Solenthaler & Pajarola 2009)", "eta",
      "below 1.5 eta (new neighbours the step's lists miss)", summed.largest_at_particles);
  EXPECT_LT(summed.largest_at_particles, 1.5 * eta);
  EXPECT_EQ(summed.at_maximum, 0);
}

TEST(StoppingNorm, DfsphCheckingTheSummedDensityBoundsTheCompressionAtTheParticles) {
  expect_summed_check_bounds_the_particles("dfsph", "Bender & Koschier 2017");
}

TEST(StoppingNorm, IisphCheckingTheSummedDensityBoundsTheCompressionAtTheParticles) {
  expect_summed_check_bounds_the_particles("iisph", "Ihmsen et al. 2014");
}

}  // namespace
}  // namespace upf
