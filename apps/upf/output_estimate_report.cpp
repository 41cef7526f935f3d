#include "output_estimate_report.h"

#include <string>

namespace upf::app {

namespace {
std::string human_bytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1000 && u < 5) {
    bytes /= 1000;
    ++u;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);  // three digits
  return text;
}
}  // namespace

void report_output_estimate(const OutputEstimate& e, const SceneDescription& scene, bool quiet,
                            std::FILE* out) {
  const std::string total = human_bytes(double(e.total_bytes));
  const char* bound = e.compressed ? "at most " : "";
  if (!quiet) {
    std::string line =
        "frames: " + std::to_string(e.frames) + " x " + human_bytes(double(e.bytes_per_frame));
    if (e.bytes_once > 0) line += " + " + human_bytes(double(e.bytes_once)) + " once (frozen)";
    line += " = " + std::string(bound) + total;
    if (e.compressed) line += " before zlib compression";
    if (e.surface) line += ", plus the surface meshes";
    std::fprintf(out, "%s\n", line.c_str());
  }
  const double limit = scene.output.size_warning_gb * 1e9;
  if (double(e.total_bytes) > limit)
    std::fprintf(out,
                 "warning: the frames may take %s%s, more than %s:/output/size_warning (%g GB); "
                 "fewer frames (/output/fps), fewer fields (/output/fields), fewer types "
                 "(/output/types) or \"compression\": \"zlib\" write less\n",
                 bound, total.c_str(), scene.source.string().c_str(), scene.output.size_warning_gb);
}

}  // namespace upf::app
