// The comparison's PNG plots, one curve per solver: density error, time step, and each probe
// against simulated time; and accuracy against cost, one point per solver (the largest density
// error against wall seconds per simulated second). scripts/plot_compare.py draws them with
// matplotlib from report.json and the runs' metrics.csv and probes.csv; this side names the files
// and checks they appeared.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/compare/comparison.h"

namespace upf {

// Every plot has this pixel size (a 12 x 7 inch figure at 100 dpi).
inline constexpr int kPlotWidthPx = 1200;
inline constexpr int kPlotHeightPx = 700;

struct PlotSpec {
  std::string file;  // relative to the comparison's output directory
  std::string title;
  std::string kind;   // "density_error", "dt", "probe" or "accuracy_cost"
  std::string probe;  // kind "probe": the probe's name
  std::string label;  // kind "probe": the y axis, "name [unit]"
};

std::vector<PlotSpec> plan_plots(const Comparison& c);

struct PlotOutcome {
  bool ok = false;
  std::string error;  // why the plots are missing
};

// Runs `script OUT` (which reads OUT/report.json, so write that first), logging to OUT/plots.log,
// then checks that every planned file exists.
PlotOutcome draw_plots(const std::filesystem::path& out_dir, const std::filesystem::path& script,
                       const std::vector<PlotSpec>& plots);

}  // namespace upf
