#include "solvers/dem/dem_wall_forces.h"

#include "framework/core/deterministic_sum.h"

namespace upf {

namespace {

// The first container whose box widened by r holds x, or boxes.size().
std::size_t container_of(const Vec3& x, Real r, const std::vector<ContainerBox>& boxes) {
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    bool inside = true;
    for (int a = 0; a < 3; ++a)
      inside = inside && x[a] > boxes[b].min[a] - r && x[a] < boxes[b].max[a] + r;
    if (inside) return b;
  }
  return boxes.size();
}

struct FaceSums {
  std::array<FixedPointAccumulator, 6> normal;
  std::array<FixedPointAccumulator, 3> shear;
};

}  // namespace

const std::array<const char*, 6>& container_face_names() {
  static constexpr std::array<const char*, 6> kNames{"x_min", "x_max", "y_min",
                                                     "y_max", "z_min", "z_max"};
  return kNames;
}

std::vector<ContainerWallForces> container_wall_forces(const Particles& particles,
                                                       const std::vector<ContainerBox>& boxes,
                                                       OwnedMaterials owns, const Vec3* wall_normal,
                                                       const Vec3* wall_shear, const Real* radius) {
  std::vector<FaceSums> sums(boxes.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.type[i] != ParticleType::Granular || !owns(particles.material[i])) continue;
    const Vec3& n = wall_normal[i];
    const Vec3& t = wall_shear[i];
    if (n == Vec3{} && t == Vec3{}) continue;
    const std::size_t b = container_of(particles.position[i], radius[i], boxes);
    if (b == boxes.size()) continue;
    for (int a = 0; a < 3; ++a) {
      // A positive normal force on the grain came from the lower face, which it pushes down
      // (outward): the reaction on the wall is the opposite force, reported by its size.
      if (n[a] > 0) sums[b].normal[std::size_t(2 * a)].add(double(n[a]));
      if (n[a] < 0) sums[b].normal[std::size_t(2 * a + 1)].add(-double(n[a]));
      sums[b].shear[std::size_t(a)].add(-double(t[a]));
    }
  }
  std::vector<ContainerWallForces> out(boxes.size());
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    for (std::size_t f = 0; f < 6; ++f) out[b].normal[f] = sums[b].normal[f].value();
    out[b].shear = {sums[b].shear[0].value(), sums[b].shear[1].value(), sums[b].shear[2].value()};
  }
  return out;
}

std::vector<std::string> container_wall_columns(std::size_t containers) {
  std::vector<std::string> columns;
  for (std::size_t b = 0; b < containers; ++b) {
    const std::string prefix = containers > 1 ? "container" + std::to_string(b) + "." : "";
    for (const char* face : container_face_names()) columns.push_back(prefix + face + "_normal");
    for (const char* axis : {"x", "y", "z"}) columns.push_back(prefix + "shear_" + axis);
  }
  return columns;
}

std::vector<double> container_wall_row(const std::vector<ContainerWallForces>& forces) {
  std::vector<double> row;
  for (const auto& c : forces) {
    row.insert(row.end(), c.normal.begin(), c.normal.end());
    row.insert(row.end(), {c.shear.x, c.shear.y, c.shear.z});
  }
  return row;
}

}  // namespace upf
