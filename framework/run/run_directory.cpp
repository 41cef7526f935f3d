#include "framework/run/run_directory.h"

#include <cctype>
#include <string>
#include <system_error>
#include <vector>

#include "framework/checkpoint/checkpoint_file.h"

namespace upf {

namespace {
namespace fs = std::filesystem;

// "<prefix>NNNNN.<ext>" with five digits: the frame files upf numbers.
bool numbered(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0 || name.size() < prefix.size() + 6) return false;
  for (std::size_t k = prefix.size(); k < prefix.size() + 5; ++k)
    if (!std::isdigit(static_cast<unsigned char>(name[k]))) return false;
  return name[prefix.size() + 5] == '.';
}

std::size_t remove_matching(const fs::path& dir, bool (*ours)(const std::string&)) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && ours(entry.path().filename().string()))
      doomed.push_back(entry.path());
  std::size_t removed = 0;
  for (const auto& p : doomed) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}
}  // namespace

std::size_t clear_earlier_run(const fs::path& dir) {
  std::size_t removed = 0;
  std::error_code ec;
  for (const char* name : {"particles.pvd", "metrics.csv", "probes.csv", "bodies.csv",
                           "body_forces.csv", "summary.json", "scene.json", kCheckpointFileName})
    removed += fs::remove(dir / name, ec) ? 1 : 0;
  // The DEM solvers' tables (DemSolver::tables): dem_<model>_walls.csv, "_2" ... when repeated.
  removed += remove_matching(dir, [](const std::string& n) {
    return n.rfind("dem_", 0) == 0 && n.find("_walls") != std::string::npos &&
           fs::path(n).extension() == ".csv";
  });
  removed += remove_matching(dir / "frames", [](const std::string& n) {
    return numbered(n, "frame_") || numbered(n, "surface_") || numbered(n, "bodies_") ||
           n == "frozen.vtp";
  });
  removed += remove_matching(dir / "render", [](const std::string& n) {
    return numbered(n, "frame_") || fs::path(n).extension() == ".mp4";
  });
  return removed;
}

}  // namespace upf
