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
  const auto [low, high] = render::widened_if_flat({scale.low, scale.high});
  scale.low = low;
  scale.high = high;
  return scale;
}

}  // namespace upf::viewer
