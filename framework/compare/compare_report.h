// Writes a comparison's reports into its output directory: report.json, the PNG plots,
// report.md and report.html. Plots come from a Python script; when it cannot run, the tables are
// still written and the reports say why the plots are missing.
#pragma once

#include <filesystem>

#include "framework/compare/comparison.h"
#include "framework/compare/plots.h"

namespace upf {

// Every file is written atomically, and report.json first (the plot script reads it), so a
// failing plot step loses nothing already written. Throws OutputError when a report cannot be
// written; a plot failure is only returned.
PlotOutcome write_compare_report(const Comparison& c, const std::filesystem::path& out_dir,
                                 const std::filesystem::path& plot_script);

}  // namespace upf
