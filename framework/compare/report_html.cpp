#include "framework/compare/report_documents.h"
#include "framework/compare/report_table.h"
#include "framework/output/vtp_writer.h"  // xml_escape

namespace upf {

namespace {
// XML escaping suits HTML too.
std::string escape(const std::string& text) {
  return xml_escape(text);
}

std::string tag(const std::string& name, const std::string& text) {
  return "<" + name + ">" + escape(text) + "</" + name + ">";
}

constexpr const char* kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 1280px; padding: 0 1em;
       color: #222; line-height: 1.4; }
h1, h2, h3 { font-weight: 600; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.3em 0.6em; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.unstable td { background: #fff0f0; }
img { max-width: 100%; height: auto; border: 1px solid #ddd; }
.missing { color: #a00; font-weight: 600; }
)";
}  // namespace

std::string report_html(const Comparison& c, const std::vector<PlotSpec>& plots,
                        const PlotOutcome& drawn) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += "<title>" + escape("Solver comparison: " + c.scene) + "</title>\n<style>" + kStyle +
       "</style>\n</head>\n<body>\n";
  h += tag("h1", "Solver comparison: " + c.scene) + "\n<ul>\n";
  for (const auto& [key, value] : report_facts(c))
    h += "<li><strong>" + escape(key) + "</strong>: " + escape(value) + "</li>\n";
  h += "</ul>\n" + tag("h2", "Results") + "\n<table>\n<tr>";

  const ReportTable table = make_report_table(c);
  for (const auto& column : table.header) h += tag("th", column);
  h += "</tr>\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    h += c.rows[r].unstable() ? "<tr class=\"unstable\">" : "<tr>";
    for (std::size_t i = 0; i < table.rows[r].size(); ++i)
      h += (i < 2 ? "<td>" : "<td class=\"num\">") + escape(table.rows[r][i]) + "</td>";
    h += "</tr>\n";
  }
  h += "</table>\n<p>Columns:</p>\n<ul>\n";
  for (const auto& [column, meaning] : column_notes())
    h += "<li><em>" + escape(column) + "</em>: " + escape(meaning) + "</li>\n";
  h += "</ul>\n";

  if (c.any_unstable()) {
    h += tag("h2", "Failures") + "\n<ul>\n";
    for (const auto& row : c.rows)
      if (row.unstable())
        h += "<li><strong>" + escape(row.name) + "</strong>: " + escape(row.result.failure) +
             "</li>\n";
    h += "</ul>\n";
  }

  h += tag("h2", "Plots") + "\n";
  h += drawn.ok ? tag("p", plots_sentence(drawn))
                : "<p class=\"missing\">" + escape(plots_sentence(drawn)) + "</p>";
  h += "\n";
  if (drawn.ok)
    for (const auto& p : plots)
      h += tag("h3", p.title) + "\n<img src=\"" + escape(p.file) + "\" width=\"" +
           std::to_string(kPlotWidthPx) + "\" height=\"" + std::to_string(kPlotHeightPx) +
           "\" alt=\"" + escape(p.title) + "\">\n";
  h += "<p>Each solver's full output (frames, metrics.csv, probes.csv, summary.json) is in its "
       "own folder next to this report.</p>\n</body>\n</html>\n";
  return h;
}

}  // namespace upf
