#include "coupling/sampling/gap_filling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace upf {

namespace {

struct Corners {
  Eigen::Vector3d a, b, c;
};

class GapFiller {
 public:
  GapFiller(double coverage, double min_distance, SampleSet& samples)
      : coverage_(coverage), min_distance_(min_distance), samples_(samples) {}

  void fill(const Corners& triangle, std::uint32_t index) {
    pending_.push_back(triangle);
    while (!pending_.empty()) {
      const Corners tri = pending_.back();
      pending_.pop_back();
      visit(tri, index);
    }
  }

 private:
  void visit(const Corners& tri, std::uint32_t index) {
    const Eigen::Vector3d centroid = (tri.a + tri.b + tri.c) / 3;
    // Every point of the triangle is within `reach` of its centroid (distance is convex).
    const double reach =
        std::sqrt(std::max({(tri.a - centroid).squaredNorm(), (tri.b - centroid).squaredNorm(),
                            (tri.c - centroid).squaredNorm()}));
    if (inside_one_ball(tri, centroid, reach)) return;
    if (reach <= coverage_ - min_distance_) {
      if (!samples_.grid().any_within(centroid, coverage_ - reach)) samples_.add(centroid, index);
      return;
    }
    const Eigen::Vector3d ab = (tri.a + tri.b) / 2, bc = (tri.b + tri.c) / 2,
                          ca = (tri.c + tri.a) / 2;
    pending_.push_back({tri.a, ab, ca});
    pending_.push_back({ab, tri.b, bc});
    pending_.push_back({ca, bc, tri.c});
    pending_.push_back({ab, bc, ca});
  }

  bool inside_one_ball(const Corners& tri, const Eigen::Vector3d& centroid, double reach) const {
    if (reach > 2 * coverage_) return false;  // no ball of radius `coverage` can hold it
    const double r2 = coverage_ * coverage_;
    // A ball holding the triangle holds its centroid: its centre is within `coverage` of it.
    return samples_.grid().visit_near(centroid, coverage_, [&](std::uint32_t sample) {
      const Eigen::Vector3d& s = samples_.grid().points()[sample];
      return (tri.a - s).squaredNorm() <= r2 && (tri.b - s).squaredNorm() <= r2 &&
             (tri.c - s).squaredNorm() <= r2;
    });
  }

  double coverage_, min_distance_;
  SampleSet& samples_;
  std::vector<Corners> pending_;
};

}  // namespace

void fill_gaps(const TriangleMesh& mesh, double coverage, double min_distance, SampleSet& samples) {
  GapFiller filler(coverage, min_distance, samples);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!(triangle_area(mesh, t) > 0)) continue;
    const auto& i = mesh.triangles[t];
    filler.fill({mesh.vertices[i[0]], mesh.vertices[i[1]], mesh.vertices[i[2]]}, t);
  }
}

}  // namespace upf
