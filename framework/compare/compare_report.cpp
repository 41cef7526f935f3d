#include "framework/compare/compare_report.h"

#include "framework/compare/report_documents.h"
#include "framework/compare/report_json.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace {
void write_text(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}
}  // namespace

PlotOutcome write_compare_report(const Comparison& c, const std::filesystem::path& out_dir,
                                 const std::filesystem::path& plot_script) {
  ensure_directory(out_dir);
  const auto plots = plan_plots(c);
  const std::filesystem::path json = out_dir / "report.json";
  write_text(json, report_json(c, plots, std::nullopt).dump(2) + "\n");
  const PlotOutcome drawn = draw_plots(out_dir, plot_script, plots);
  write_text(json, report_json(c, plots, drawn).dump(2) + "\n");
  write_text(out_dir / "report.md", report_markdown(c, plots, drawn));
  write_text(out_dir / "report.html", report_html(c, plots, drawn));
  return drawn;
}

}  // namespace upf
