// Points in a uniform grid of cubic cells kept in a hash map: "is a point within r of x?" in
// constant time, for any extent (only occupied cells cost memory). With cells at least twice the
// query radius, a query looks into at most 2 x 2 x 2 cells.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace upf {

class SampleGrid {
 public:
  // Callers keep coordinates / cell_size well inside +-2^62 (the sampler checks the extent).
  explicit SampleGrid(double cell_size) : cell_size_(cell_size) {}

  void insert(const Eigen::Vector3d& point);
  const std::vector<Eigen::Vector3d>& points() const { return points_; }

  // Calls visit(index) for the points in the cells the ball (x, radius) touches (a superset of
  // the points within radius: callers test the distance) until visit returns true. Returns
  // whether a visit returned true.
  template <class Visit>
  bool visit_near(const Eigen::Vector3d& x, double radius, Visit&& visit) const {
    const Cell lo = cell_of((x.array() - radius).matrix());
    const Cell hi = cell_of((x.array() + radius).matrix());
    for (std::int64_t i = lo.i; i <= hi.i; ++i)
      for (std::int64_t j = lo.j; j <= hi.j; ++j)
        for (std::int64_t k = lo.k; k <= hi.k; ++k) {
          auto it = cells_.find(Cell{i, j, k});
          if (it == cells_.end()) continue;
          for (const std::uint32_t index : it->second)
            if (visit(index)) return true;
        }
    return false;
  }

  // Squared distance from x to the nearest point within `radius`; infinity when there is none.
  double nearest_squared_distance(const Eigen::Vector3d& x, double radius) const;
  bool any_within(const Eigen::Vector3d& x, double radius) const;

 private:
  struct Cell {
    std::int64_t i, j, k;
    bool operator==(const Cell&) const = default;
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  Cell cell_of(const Eigen::Vector3d& x) const;

  double cell_size_;
  std::vector<Eigen::Vector3d> points_;
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells_;
};

}  // namespace upf
