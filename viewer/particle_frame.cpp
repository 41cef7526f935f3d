#include "viewer/particle_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace upf::viewer {

render::PolyData to_poly_data(const Particles& p) {
  render::PolyData out;
  const std::size_t n = p.size();
  out.points.reserve(n);
  for (const Vec3& x : p.position) out.points.emplace_back(float(x.x), float(x.y), float(x.z));
  auto scalar = [&](std::string name, auto value) {
    render::VtpArray a{std::move(name), 1, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) a.values[i] = value(i);
    out.point_data.push_back(std::move(a));
  };
  auto vector = [&](std::string name, const std::vector<Vec3>& v) {
    render::VtpArray a{std::move(name), 3, std::vector<double>(3 * n)};
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) a.values[3 * i + std::size_t(c)] = double(v[i][c]);
    out.point_data.push_back(std::move(a));
  };
  scalar("type", [&](std::size_t i) { return double(int(p.type[i])); });
  scalar("material", [&](std::size_t i) { return double(p.material[i]); });
  vector("velocity", p.velocity);
  for (const auto& [name, field] : p.scalar_fields()) {
    // clang 14 cannot capture a structured binding: capture the values by a plain reference.
    const std::vector<Real>& values = field.values;
    if (field.exported && values.size() == n)
      scalar(name, [&values](std::size_t i) { return double(values[i]); });
  }
  for (const auto& [name, field] : p.vector_fields())
    if (field.exported && field.values.size() == n && name != "velocity")
      vector(name, field.values);
  return out;
}

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
