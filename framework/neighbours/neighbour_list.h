// Compact neighbour lists (CSR): the neighbours of particle i are
// indices[offsets[i] .. offsets[i+1]). Particles outside the query set have empty lists.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace upf {

// A particle's neighbours as a range (C++17, so the header stays nvcc-clean).
struct IndexRange {
  const std::uint32_t* first;
  const std::uint32_t* last;
  const std::uint32_t* begin() const { return first; }
  const std::uint32_t* end() const { return last; }
  std::size_t size() const { return std::size_t(last - first); }
};

struct NeighbourList {
  std::vector<std::uint32_t> offsets;  // size() + 1 entries
  std::vector<std::uint32_t> indices;

  IndexRange of(std::size_t i) const {
    return {indices.data() + offsets[i], indices.data() + offsets[i + 1]};
  }
  std::size_t total() const { return indices.size(); }
};

// A raw view for per-particle functions (host and device).
struct NeighbourView {
  const std::uint32_t* offsets = nullptr;
  const std::uint32_t* indices = nullptr;
};

inline NeighbourView view_of(const NeighbourList& list) {
  return {list.offsets.data(), list.indices.data()};
}

}  // namespace upf
