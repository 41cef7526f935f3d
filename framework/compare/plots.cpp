#include "framework/compare/plots.h"

#include <cctype>
#include <system_error>

#include "framework/compare/python_runner.h"

namespace upf {

namespace {
// Probe names are free text in the scene: keep file names to safe characters.
std::string file_stem(const std::string& name) {
  std::string s;
  for (unsigned char ch : name) s += std::isalnum(ch) || ch == '-' || ch == '_' ? char(ch) : '_';
  return s;
}
}  // namespace

std::vector<PlotSpec> plan_plots(const Comparison& c) {
  std::vector<PlotSpec> plots = {
      {"density_error.png", "Density error (average and maximum) vs time", "density_error", "", ""},
      {"dt.png", "Time step vs time", "dt", "", ""},
      {"accuracy_cost.png",
       "Largest density error vs wall seconds per simulated second, one point per run",
       "accuracy_cost", "", ""}};
  for (std::size_t i = 0; i < c.probes.size(); ++i) {
    const std::string& name = c.probes[i];
    // The index keeps two names that sanitise alike ("a b", "a_b") apart.
    plots.push_back({"probe_" + std::to_string(i + 1) + "_" + file_stem(name) + ".png",
                     "Probe " + name + " vs time", "probe", name, c.probe_label(i)});
  }
  return plots;
}

PlotOutcome draw_plots(const std::filesystem::path& out_dir, const std::filesystem::path& script,
                       const std::vector<PlotSpec>& plots) {
  PlotOutcome outcome;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(script, ec)) {
    outcome.error =
        "plot script " + script.string() + " not found (give --plot-script or set UPF_PLOT_SCRIPT)";
    return outcome;
  }
  // Stale pictures from an earlier comparison must not pass for new ones.
  for (const auto& p : plots) std::filesystem::remove(out_dir / p.file, ec);
  const std::filesystem::path log = out_dir / "plots.log";
  std::filesystem::remove(log, ec);
  const PythonRun run = run_python_script(script, {out_dir.string()}, log);
  if (!run.ok) {
    outcome.error = run.error;
    return outcome;
  }
  for (const auto& p : plots)
    if (!std::filesystem::is_regular_file(out_dir / p.file, ec)) {
      outcome.error = script.string() + " did not write " + p.file;
      return outcome;
    }
  outcome.ok = true;
  return outcome;
}

}  // namespace upf
