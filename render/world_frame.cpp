#include "render/world_frame.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "framework/world/body_system.h"

namespace upf::render {

PolyData particles_poly_data(const Particles& p) {
  PolyData out;
  const std::size_t n = p.size();
  out.points.reserve(n);
  for (const Vec3& x : p.position) out.points.emplace_back(float(x.x), float(x.y), float(x.z));
  auto scalar = [&](std::string name, auto value) {
    VtpArray a{std::move(name), 1, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) a.values[i] = value(i);
    out.point_data.push_back(std::move(a));
  };
  auto vector = [&](std::string name, const std::vector<Vec3>& v) {
    VtpArray a{std::move(name), 3, std::vector<double>(3 * n)};
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

PolyData meshes_poly_data(const std::vector<MeshPiece>& pieces) {
  PolyData out;
  VtpArray body{"body", 1, {}};
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto base = std::uint32_t(out.points.size());
    for (const Eigen::Vector3d& v : pieces[k].vertices) out.points.push_back(v.cast<float>());
    for (const auto& t : pieces[k].triangles) {
      out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      body.values.push_back(double(k));
    }
  }
  out.cell_data.push_back(std::move(body));
  return out;
}

FrameData world_frame(const World& world) {
  FrameData frame;
  frame.time = world.time();
  frame.particles = particles_poly_data(world.particles());
  for (const auto& system : world.body_systems()) {
    const std::vector<MeshPiece> pieces = system->surface_meshes();
    if (!pieces.empty()) frame.meshes.push_back(meshes_poly_data(pieces));
  }
  return frame;
}

}  // namespace upf::render
