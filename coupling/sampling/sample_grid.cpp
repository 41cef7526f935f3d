#include "coupling/sampling/sample_grid.h"

#include <algorithm>

namespace upf {

std::size_t SampleGrid::CellHash::operator()(const Cell& c) const {
  // Large odd multipliers spread neighbouring cells over the buckets.
  const auto h = std::uint64_t(c.i) * 0x9E3779B97F4A7C15ull ^
                 std::uint64_t(c.j) * 0xC2B2AE3D27D4EB4Full ^
                 std::uint64_t(c.k) * 0x165667B19E3779F9ull;
  return static_cast<std::size_t>(h ^ (h >> 31));
}

SampleGrid::Cell SampleGrid::cell_of(const Eigen::Vector3d& x) const {
  return {static_cast<std::int64_t>(std::floor(x.x() / cell_size_)),
          static_cast<std::int64_t>(std::floor(x.y() / cell_size_)),
          static_cast<std::int64_t>(std::floor(x.z() / cell_size_))};
}

void SampleGrid::insert(const Eigen::Vector3d& point) {
  cells_[cell_of(point)].push_back(static_cast<std::uint32_t>(points_.size()));
  points_.push_back(point);
}

double SampleGrid::nearest_squared_distance(const Eigen::Vector3d& x, double radius) const {
  double nearest = std::numeric_limits<double>::infinity();
  visit_near(x, radius, [&](std::uint32_t index) {
    nearest = std::min(nearest, (points_[index] - x).squaredNorm());
    return false;
  });
  return nearest <= radius * radius ? nearest : std::numeric_limits<double>::infinity();
}

bool SampleGrid::any_within(const Eigen::Vector3d& x, double radius) const {
  return visit_near(x, radius, [&](std::uint32_t index) {
    return (points_[index] - x).squaredNorm() <= radius * radius;
  });
}

}  // namespace upf
