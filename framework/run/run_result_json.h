// A run's figures as JSON: summary.json and the comparison's report.json show them under the same
// keys (docs/solvers.md, "summary.json keys"). Non-finite values become null.
#pragma once

#include <nlohmann/json.hpp>

#include "framework/run/simulation_run.h"

namespace upf {

nlohmann::json run_result_json(const RunResult& r);

}  // namespace upf
