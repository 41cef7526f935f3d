#include "coupling/sampling/dart_throwing.h"

#include <random>

namespace upf {

namespace {
// Uniform in [0, 1) from the top 53 bits: the same double on every platform.
double unit_random(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
}  // namespace

void throw_darts(const TriangleMesh& mesh, double radius, double darts_per_disk, std::uint64_t seed,
                 SampleSet& samples) {
  constexpr double kPi = 3.14159265358979323846;
  const double darts_per_area = darts_per_disk / (kPi * radius * radius);
  std::mt19937_64 rng(seed);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const double area = triangle_area(mesh, t);
    if (!(area > 0)) continue;
    // Stochastic rounding keeps the expected count proportional to the area.
    const double expected = area * darts_per_area;
    auto count = static_cast<std::uint64_t>(expected);
    if (unit_random(rng) < expected - static_cast<double>(count)) ++count;
    const auto& i = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[i[0]];
    const Eigen::Vector3d ab = mesh.vertices[i[1]] - a, ac = mesh.vertices[i[2]] - a;
    for (std::uint64_t n = 0; n < count; ++n) {
      double u = unit_random(rng), v = unit_random(rng);
      if (u + v > 1) {  // fold the far half of the parallelogram back onto the triangle
        u = 1 - u;
        v = 1 - v;
      }
      const Eigen::Vector3d p = a + u * ab + v * ac;
      if (!samples.grid().any_within(p, radius)) samples.add(p, t);
    }
  }
}

}  // namespace upf
