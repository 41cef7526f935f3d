// report.md and report.html: the same content for people, in two formats: the facts, the table,
// what each column means, the failures, and the plots (or why they are missing). The HTML shows
// the PNG files next to it inline and needs nothing else.
#pragma once

#include <string>
#include <vector>

#include "framework/compare/comparison.h"
#include "framework/compare/plots.h"

namespace upf {

std::string report_markdown(const Comparison& c, const std::vector<PlotSpec>& plots,
                            const PlotOutcome& drawn);
std::string report_html(const Comparison& c, const std::vector<PlotSpec>& plots,
                        const PlotOutcome& drawn);

// The sentence both formats show about the plots.
std::string plots_sentence(const PlotOutcome& drawn);

}  // namespace upf
