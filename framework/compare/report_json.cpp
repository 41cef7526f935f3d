#include "framework/compare/report_json.h"

#include <cmath>

#include "framework/run/run_result_json.h"

namespace upf {

namespace {
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// The run's summary figures plus where it failed; `dir` is the run's folder under OUT/.
nlohmann::json row_json(const CompareRow& row) {
  nlohmann::json j = run_result_json(row.result);
  j["solver"] = row.solver;
  j["run"] = row.name;
  j["dir"] = row.name;
  if (!row.unstable()) j["failure"] = nullptr;
  j["failure_time_s"] = row.unstable() ? number(row.result.simulated_time) : nullptr;
  return j;
}
}  // namespace

nlohmann::json report_json(const Comparison& c, const std::vector<PlotSpec>& plots,
                           const std::optional<PlotOutcome>& drawn) {
  nlohmann::json j = {{"scene", c.scene},
                      {"source", c.source},
                      {"date", c.date},
                      {"threads", c.threads},
                      {"end_time_s", c.end_time},
                      {"probes", c.probes},
                      {"probe_units", c.probe_units},
                      {"particles", {{"liquid", c.liquid_particles}, {"total", c.total_particles}}},
                      {"rows", nlohmann::json::array()}};
  for (const auto& row : c.rows) j["rows"].push_back(row_json(row));

  nlohmann::json p;
  p["status"] = !drawn ? "pending" : drawn->ok ? "drawn" : "missing";
  if (drawn && !drawn->ok) p["error"] = drawn->error;
  p["width_px"] = kPlotWidthPx;
  p["height_px"] = kPlotHeightPx;
  p["files"] = nlohmann::json::array();
  for (const auto& s : plots)
    p["files"].push_back(
        {{"file", s.file},
         {"title", s.title},
         {"kind", s.kind},
         {"probe", s.probe.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.probe)},
         {"label", s.label.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.label)}});
  j["plots"] = p;
  return j;
}

}  // namespace upf
