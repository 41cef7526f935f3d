#include "viewer/frame_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace upf::viewer {

std::optional<render::ColourScale> frame_scale(const render::PolyData& p,
                                               const std::string& field) {
  if (field == "type" || field == "material" || !render::frame_has_field(p, field))
    return std::nullopt;
  render::ColourScale scale{field, 0, 1};
  if (auto r = render::field_percentiles(p, field)) {
    scale.low = (*r)[0];
    scale.high = (*r)[1];
  }
  if (scale.high - scale.low < 1e-12 * std::max(1.0, std::abs(scale.high))) {
    scale.low -= 0.5;
    scale.high += 0.5;
  }
  return scale;
}

}  // namespace upf::viewer
