#include "framework/compare/report_documents.h"
#include "framework/compare/report_table.h"
#include "framework/core/markdown_cell.h"

namespace upf {

namespace {
std::string table_row(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const auto& c : cells) out += " " + markdown_cell(c) + " |";
  return out + "\n";
}
}  // namespace

std::string plots_sentence(const PlotOutcome& drawn) {
  if (drawn.ok)
    return "One curve per solver; each picture is " + std::to_string(kPlotWidthPx) + " x " +
           std::to_string(kPlotHeightPx) + " pixels.";
  return "The plots are missing: " + drawn.error + ". The tables above are complete.";
}

std::string report_markdown(const Comparison& c, const std::vector<PlotSpec>& plots,
                            const PlotOutcome& drawn) {
  std::string md = "# Solver comparison: " + c.scene + "\n\n";
  for (const auto& [key, value] : report_facts(c)) md += "- **" + key + "**: " + value + "\n";

  const ReportTable table = make_report_table(c);
  md += "\n## Results\n\n" + table_row(table.header) + "|";
  for (std::size_t i = 0; i < table.header.size(); ++i) md += i < 2 ? "---|" : "---:|";
  md += "\n";
  for (const auto& r : table.rows) md += table_row(r);
  md += "\nColumns:\n\n";
  for (const auto& [column, meaning] : column_notes())
    md += "- *" + column + "*: " + meaning + "\n";

  if (c.any_unstable()) {
    md += "\n## Failures\n\n";
    for (const auto& row : c.rows)
      if (row.unstable()) md += "- **" + row.name + "**: " + row.result.failure + "\n";
  }

  md += "\n## Plots\n\n" + plots_sentence(drawn) + "\n";
  if (drawn.ok)
    for (const auto& p : plots)
      md += "\n### " + p.title + "\n\n![" + p.title + "](" + p.file + ")\n";
  md +=
      "\nEach solver's full output (frames, metrics.csv, probes.csv, summary.json) is in its own "
      "folder next to this report.\n";
  return md;
}

}  // namespace upf
