// SPHERIC Test 2 (Kleefsman et al. 2005, "A Volume-of-Fluid based simulation method for wave
// impact problems", J. Comput. Phys. 206; the MARIN experiment): a dam break onto a box, run at
// 5 cm spacing (5,280 liquid particles) for 1.5 s with PCISPH and compared against the measured
// traces in tests/data/spheric_test2/ (their source is in SOURCE.md there).
//
// What a coarse run must get right, and what it cannot:
//   - the reservoir drains as measured (gauge H4) and the water depth in front of the box (H2)
//     follows the experiment: volume and gravity-driven flow;
//   - the front reaches the gauge at 1.488 m (H3) and the box (P1) when the experiment does;
//   - the pressure on the lower half of the box's front face (P1-P3, 0.6-1.5 s, after the first
//     impact) is the measured pressure within 35 %. With Akinci et al.'s boundary term alone it
//     reads 2.2 times that (docs/boundary-pressure.md); the wall pressure of Adami et al. 2012
//     (solver parameter wall_pressure, which the sample sets) brings it to 1.1-1.3 times.
//   - the first-impact peak is not compared: a coarse weakly resolved impact spikes far above.
// The finer run of samples/spheric_test2.json and its plot are bench/spheric_test2.sh and
// docs/validation-spheric-test2.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "framework/run/probes.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf {
namespace {

// A time series per column: {"t": [...], "P1": [...], ...}.
using Series = std::map<std::string, std::vector<double>>;

// One of the stored experiment files; its columns are "time_s" and "<name>_<unit>".
Series read_experiment(const std::string& file) {
  std::ifstream in(std::filesystem::path(UPF_SOURCE_DIR) / "tests" / "data" / "spheric_test2" /
                   file);
  Series series;
  std::string line;
  std::vector<std::string> names;
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');)
    names.push_back(cell == "time_s" ? "t" : cell.substr(0, cell.find('_')));
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (const auto& name : names) {
      std::getline(row, cell, ',');
      series[name].push_back(std::stod(cell));
    }
  }
  return series;
}

double window_mean(const Series& s, const std::string& name, double from, double to) {
  double sum = 0;
  int count = 0;
  const auto& t = s.at("t");
  const auto& v = s.at(name);
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from && t[i] < to && std::isfinite(v[i])) {
      sum += v[i];
      ++count;
    }
  return count ? sum / count : std::nan("");
}

// The first time `name` exceeds `threshold`, or NaN.
double first_above(const Series& s, const std::string& name, double threshold) {
  const auto& v = s.at(name);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] > threshold) return s.at("t")[i];
  return std::nan("");
}

// The sample at 5 cm, stepped to `end` with every probe sampled after every step.
Series run_coarse(double end) {
  auto doc = testing::load_sample_json("spheric_test2.json");
  doc["particle_spacing"] = 0.05;
  doc["bodies"][0]["mesh"]["file"] =
      (std::filesystem::path(UPF_SOURCE_DIR) / "assets" / "meshes" / "unit_box.obj").string();
  testing::TestWorld tw(doc, 2);
  World& w = *tw.world;
  Series s;
  auto sample = [&] {
    s["t"].push_back(w.time());
    for (const auto& probe : tw.scene.probes)
      s[probe.name].push_back(evaluate_probe(probe, w.particles(), Real(tw.scene.world.spacing)));
  };
  sample();
  while (w.time() < end - 1e-12) {
    w.step(w.next_time_step_until(end));
    sample();
  }
  return s;
}

Series experiment_traces() {
  Series s = read_experiment("pressures.csv");
  for (auto& [name, values] : read_experiment("heights.csv"))
    if (name != "t") s[name] = values;
  return s;
}

TEST(SphericTest2, TheStoredExperimentIsTheMarinDamBreak) {
  // Guards the data files: the reservoir gauge starts at the 0.55 m column, the gauge at 1.488 m
  // (nearest the door) wets first, and P1 (lowest on the box) rises at 0.40 s.
  const Series experiment = experiment_traces();
  EXPECT_NEAR(experiment.at("H4").front(), 0.55, 0.005);
  EXPECT_LT(first_above(experiment, "H3", 0.03), first_above(experiment, "H2", 0.03));
  EXPECT_LT(first_above(experiment, "H2", 0.03), first_above(experiment, "H1", 0.03));
  EXPECT_NEAR(first_above(experiment, "P1", 2000), 0.40, 0.01);
}

// The mean of gauge `name` over [from, to) within `tolerance` (relative) of the experiment's,
// printed and recorded for docs/validation.md.
void expect_gauge_window(const Series& experiment, const Series& simulation,
                         const std::string& name, const std::string& gauge, double from, double to,
                         double tolerance) {
  const double measured = window_mean(experiment, name, from, to);
  const double simulated = window_mean(simulation, name, from, to);
  char label[96], expected[32], bound[32];
  std::snprintf(label, sizeof label, "%s, mean over %.1f-%.1f s", gauge.c_str(), from, to);
  std::snprintf(expected, sizeof expected, "%.4f m", measured);
  std::snprintf(bound, sizeof bound, "within %g %%", 100 * tolerance);
  std::printf("%s: measured %.4f m, simulated %.4f m\n", label, measured, simulated);
  testing::record_validation(label, "Kleefsman et al. 2005 (MARIN)", expected, bound, simulated,
                             "m");
  EXPECT_NEAR(simulated, measured, tolerance * measured) << label;
}

// One run (8 s on two threads), three comparisons.
TEST(SphericTest2, CoarseRunFollowsTheExperiment) {
  const Series experiment = experiment_traces();
  const Series simulation = run_coarse(1.5);

  // The reservoir drains and the water piles up in front of the box as measured.
  for (auto [from, to] : {std::pair{0.4, 0.6}, {0.6, 1.0}, {1.0, 1.5}})
    expect_gauge_window(experiment, simulation, "H4", "reservoir gauge H4", from, to, 0.04);
  for (auto [from, to] : {std::pair{0.6, 1.0}, {1.0, 1.5}})
    expect_gauge_window(experiment, simulation, "H2", "gauge H2 (x = 0.992 m)", from, to, 0.12);

  // The front reaches the gauge and the box when measured; a 5 cm front is a row or two of
  // particles, and lags by a few hundredths of a second.
  const double h3 = first_above(experiment, "H3", 0.03);
  const double h3_sim = first_above(simulation, "H3", 0.03);
  const double p1 = first_above(experiment, "P1", 2000);
  const double p1_sim = first_above(simulation, "P1", 2000);
  std::printf("H3 wets at %.3f s (measured %.3f s); P1 passes 2 kPa at %.3f s (measured %.3f s)\n",
              h3_sim, h3, p1_sim, p1);
  char expected[32];
  std::snprintf(expected, sizeof expected, "%.3f s", h3);
  testing::record_validation("gauge H3 (x = 1.488 m) wets (0.03 m)",
                             "Kleefsman et al. 2005 (MARIN)", expected, "within 0.05 s", h3_sim,
                             "s");
  std::snprintf(expected, sizeof expected, "%.3f s", p1);
  testing::record_validation("sensor P1 passes 2 kPa (first impact)",
                             "Kleefsman et al. 2005 (MARIN)", expected, "within 0.05 s", p1_sim,
                             "s");
  EXPECT_NEAR(h3_sim, h3, 0.05);
  EXPECT_NEAR(p1_sim, p1, 0.05);

  // The pressure on the lower half of the box's front face after the first impact.
  double measured = 0, simulated = 0;
  for (const char* sensor : {"P1", "P2", "P3"}) {
    const double p = window_mean(experiment, sensor, 0.6, 1.5);
    const double p_sim = window_mean(simulation, sensor, 0.6, 1.5);
    std::printf("%s 0.6-1.5 s: measured %.0f Pa, simulated %.0f Pa (%.2fx)\n", sensor, p, p_sim,
                p_sim / p);
    measured += p;
    simulated += p_sim;
  }
  testing::record_validation("P1+P2+P3 mean over 0.6-1.5 s / measured",
                             "Kleefsman et al. 2005 (MARIN)", "1", "within 35 %",
                             simulated / measured);
  EXPECT_NEAR(simulated / measured, 1.0, 0.35);
}

}  // namespace
}  // namespace upf
