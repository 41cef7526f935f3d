// The neighbour lists a device pipeline's solvers ask for, as World::request_neighbours keeps
// them: one list per (query types, target types, radius), the radius capped at the grid's cells
// (the support radius), the same request answered with the same list. All are rebuilt from the
// grid at every step's start, requests with the same query and radius in one scan, so a list
// holds the same neighbours in the same order as the world's (device_grid.h).
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

#include "device/device_grid.h"

namespace upf::device {

template <class Backend>
class DeviceLists {
 public:
  explicit DeviceLists(Real support_radius) : support_(support_radius) {}

  // A handle for view(); requests made before the first update.
  int request(TypeMask query, TypeMask target, Real radius = 0) {
    if (!(radius > 0) || radius > support_) radius = support_;
    for (std::size_t i = 0; i < requests_.size(); ++i)
      if (requests_[i].query == query && requests_[i].target == target &&
          requests_[i].radius == radius)
        return int(i);
    requests_.push_back({query, target, radius});
    lists_.emplace_back();
    return int(requests_.size() - 1);
  }

  // Every list from the grid built over the current positions.
  void update(DeviceGrid<Backend>& grid, const ParticleType* type, const BodyId* body) {
    std::vector<bool> done(requests_.size(), false);
    for (std::size_t a = 0; a < requests_.size(); ++a) {
      if (done[a]) continue;
      // At most kMaxLists targets per scan (the grid's CountStage).
      TypeMask targets[grid_detail::kMaxLists];
      DeviceNeighbourList<Backend>* outs[grid_detail::kMaxLists];
      int count = 0;
      for (std::size_t b = a; b < requests_.size() && count < grid_detail::kMaxLists; ++b) {
        if (done[b] || requests_[b].query != requests_[a].query ||
            requests_[b].radius != requests_[a].radius)
          continue;
        done[b] = true;
        targets[count] = requests_[b].target;
        outs[count] = &lists_[b];
        ++count;
      }
      // Targets beyond kMaxLists with the same query and radius are left for a later `a`.
      grid.find_neighbours(type, body, requests_[a].query, targets, count, requests_[a].radius,
                           outs);
    }
  }

  NeighbourView view(int handle) const { return lists_[std::size_t(handle)].view(); }
  const DeviceNeighbourList<Backend>& list(int handle) const { return lists_[std::size_t(handle)]; }

  std::size_t bytes() const {
    std::size_t total = 0;
    for (const auto& l : lists_) total += l.bytes();
    return total;
  }

 private:
  struct Request {
    TypeMask query, target;
    Real radius;
  };
  Real support_;
  std::vector<Request> requests_;
  std::deque<DeviceNeighbourList<Backend>> lists_;  // stable addresses
};

}  // namespace upf::device
