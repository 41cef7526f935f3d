#include "render/run_frames.h"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "framework/core/errors.h"
#include "render/xml_tags.h"

namespace upf::render {

std::vector<RunFrame> read_run_frames(const std::filesystem::path& run_dir) {
  const std::filesystem::path pvd = run_dir / "particles.pvd";
  std::ifstream in(pvd, std::ios::binary);
  if (!in)
    throw InputError(pvd.string(),
                     "cannot open the run's frame list (is this a run directory with frames?)");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<RunFrame> frames;
  try {
    for (const XmlTag& tag : read_xml_tags(text)) {
      if (tag.name != "DataSet" || tag.closing) continue;
      const auto time = tag.attribute("timestep");
      const auto file = tag.attribute("file");
      if (!time || !file) throw std::runtime_error("a DataSet without timestep or file");
      std::size_t used = 0;
      const double t = std::stod(*time, &used);
      if (used != time->size()) throw std::runtime_error("timestep \"" + *time + "\"");
      // Parts of one time step are consecutive entries with the same time (PvdSeries).
      if (frames.empty() || frames.back().time != t) frames.push_back({t, {}});
      frames.back().parts.push_back(run_dir / *file);
    }
  } catch (const std::exception& e) {
    throw InputError(pvd.string(), std::string("malformed frame list: ") + e.what());
  }
  if (frames.empty()) throw InputError(pvd.string(), "the run has no frames");
  return frames;
}

}  // namespace upf::render
