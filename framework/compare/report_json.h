// report.json: the comparison for programs: raw numbers in SI units (NaN and infinity as null),
// one object per solver, and the plots with their pixel size and whether they were drawn.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "framework/compare/comparison.h"
#include "framework/compare/plots.h"

namespace upf {

// `drawn`: nullopt while the plots are still to be drawn (the plot script reads this file).
nlohmann::json report_json(const Comparison& c, const std::vector<PlotSpec>& plots,
                           const std::optional<PlotOutcome>& drawn);

}  // namespace upf
