// The neighbour grid of the device pipeline: NeighbourGrid's lists, to the bit, built from sorts,
// scans and per-particle stages with no atomics.
//
//   keys       the Morton key of each particle's cell, with the CPU grid's origin (one cell below
//              the lowest particle) and its double-precision cell coordinates;
//   order      particles sorted by id, then stable-sorted by key: (key, id) order, as on the CPU;
//   cells      the first slot of each distinct key (a copy_if over key changes);
//   lists      per cell its 27 neighbour cells (z, y, x from -1 to 1, a binary search of the cell
//              keys each); per particle a count pass over them, a scan into CSR offsets, and a fill
//              pass that visits the candidates in the same order. A particle's list is therefore
//              the CPU's: the 27 cells in the same order, each cell's particles in id order.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <thrust/copy.h>
#include <thrust/gather.h>
#include <thrust/reduce.h>
#include <thrust/scan.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>

#include "device/device_primitives.h"
#include "framework/core/particle_type.h"
#include "framework/neighbours/morton.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf::device {

template <class Backend>
struct DeviceNeighbourList {
  typename Backend::template vector<std::uint32_t> offsets;  // size n + 1
  typename Backend::template vector<std::uint32_t> indices;
  NeighbourView view() const { return {raw<std::uint32_t>(offsets), raw<std::uint32_t>(indices)}; }
  std::size_t total() const { return indices.size(); }
  std::size_t bytes() const { return bytes_of(offsets) + bytes_of(indices); }
};

namespace grid_detail {

UPF_HD inline bool type_in(TypeMask mask, ParticleType t) {
  return ((unsigned(mask) >> unsigned(t)) & 1u) != 0;
}

// query_takes (particle_type.h) on the device: whether particle i's neighbours are listed.
UPF_HD inline bool query_takes_particle(TypeMask query, const ParticleType* type,
                                        const BodyId* body, std::size_t i) {
  if (!type_in(query, type[i])) return false;
  return (query & kOfBodiesOnly) == 0 || body[i] != kNoBody;
}

struct Vec3Min {
  UPF_HD Vec3 operator()(const Vec3& a, const Vec3& b) const {
    return {b.x < a.x ? b.x : a.x, b.y < a.y ? b.y : a.y, b.z < a.z ? b.z : a.z};
  }
};

// NeighbourGrid::cell_coords: in double, clamped into the Morton range.
UPF_HD inline std::uint32_t cell_coordinate(Real x, Real origin, Real cell_size) {
  const double cell = floor((double(x) - double(origin)) / double(cell_size));
  const double top = double(kMortonAxisMax - 1);
  return static_cast<std::uint32_t>(cell < 0.0 ? 0.0 : (cell > top ? top : cell));
}

struct KeyStage {
  const Vec3* x;
  Vec3 origin;
  Real cell_size;
  std::uint64_t* key;
  UPF_HD void operator()(std::size_t i) const {
    key[i] = morton_key(cell_coordinate(x[i].x, origin.x, cell_size),
                        cell_coordinate(x[i].y, origin.y, cell_size),
                        cell_coordinate(x[i].z, origin.z, cell_size));
  }
};

struct KeyChanges {
  const std::uint64_t* key;  // in sorted order
  UPF_HD bool operator()(std::size_t s) const { return s == 0 || key[s] != key[s - 1]; }
};

// Per cell c: the cell of each of its slots; per slot s: where particle order[s] sits.
struct CellSlotsStage {
  const std::uint32_t* cell_begin;
  const std::uint32_t* order;
  std::uint32_t* cell_of_slot;
  std::uint32_t* slot_of;
  UPF_HD void operator()(std::size_t c) const {
    for (std::uint32_t s = cell_begin[c]; s < cell_begin[c + 1]; ++s) {
      cell_of_slot[s] = std::uint32_t(c);
      slot_of[order[s]] = s;
    }
  }
};

struct SortedCopyStage {
  const std::uint32_t* order;
  const Vec3* x;
  const ParticleType* type;
  Vec3* sorted_x;
  ParticleType* sorted_type;
  UPF_HD void operator()(std::size_t s) const {
    sorted_x[s] = x[order[s]];
    sorted_type[s] = type[order[s]];
  }
};

// The grid as a per-particle stage sees it.
struct GridView {
  const std::uint64_t* cell_key;
  const std::uint32_t* cell_begin;  // cells + 1 entries
  std::size_t cells;
  const std::uint32_t* order;
  const std::uint32_t* slot_of;
  const std::uint32_t* cell_of_slot;
  const Vec3* sorted_x;
  const ParticleType* sorted_type;
  const std::uint32_t* cell_neighbours;  // 27 per cell (CellNeighboursStage)

  // The cell with key k, or `cells` when there is none.
  UPF_HD std::size_t find(std::uint64_t k) const {
    std::size_t lo = 0, hi = cells;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (cell_key[mid] < k)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo < cells && cell_key[lo] == k ? lo : cells;
  }

  // The neighbour cells of cell c, in NeighbourGrid's order, into out[27] (`cells` if missing).
  UPF_HD void find_neighbour_cells(std::size_t c, std::uint32_t* out) const {
    const std::uint64_t key = cell_key[c];
    const std::int64_t cx = std::int64_t(compact_bits_3d(key)),
                       cy = std::int64_t(compact_bits_3d(key >> 1)),
                       cz = std::int64_t(compact_bits_3d(key >> 2));
    int k = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx, ++k) {
          const std::int64_t nx = cx + dx, ny = cy + dy, nz = cz + dz;
          out[k] = std::uint32_t(cells);
          if (nx < 0 || ny < 0 || nz < 0 || nx > kMortonAxisMax || ny > kMortonAxisMax ||
              nz > kMortonAxisMax)
            continue;
          out[k] = std::uint32_t(
              find(morton_key(std::uint32_t(nx), std::uint32_t(ny), std::uint32_t(nz))));
        }
  }

  // visit(slot) for every candidate slot around particle slot s, in NeighbourGrid's order.
  template <class Visit>
  UPF_HD void for_each_candidate(std::uint32_t s, Visit& visit) const {
    const std::uint32_t* around = cell_neighbours + std::size_t(cell_of_slot[s]) * 27;
    for (int k = 0; k < 27; ++k) {
      const std::uint32_t j = around[k];
      if (j == cells) continue;
      for (std::uint32_t u = cell_begin[j]; u < cell_begin[j + 1]; ++u) visit(u);
    }
  }
};

// Per cell c: its 27 neighbour cells in NeighbourGrid's order (z, y, x from -1 to 1), the missing
// ones as `cells`: one binary search per cell and direction, shared by all its particles.
struct CellNeighboursStage {
  GridView g;
  std::uint32_t* cell_neighbours;
  UPF_HD void operator()(std::size_t c) const {
    g.find_neighbour_cells(c, cell_neighbours + c * 27);
  }
};

// Up to four lists (one query set, four target sets) in one scan, as NeighbourGrid does any
// number. CountStage and FillStage spell out four.
inline constexpr int kMaxLists = 4;
static_assert(kParticleTypeCount * kMaxLists <= 32,
              "ListRequest::lists_of_type holds 4 bits per type");
struct ListRequest {
  TypeMask query;
  TypeMask target[kMaxLists];
  int lists;
  Real radius2;
  // Bits 4t to 4t + 3: the lists that take particle type t (bit l: list l). One word, not an
  // array: on a GPU, an array indexed at run time would move the request to local memory.
  std::uint32_t lists_of_type;
  UPF_HD std::uint32_t lists_of(ParticleType t) const {
    return (lists_of_type >> (4u * unsigned(t))) & 0xFu;
  }
};

// The candidates of particle slot s within the radius: visit(j, type of j), in NeighbourGrid's
// order. The stages test the type against each list with constant list numbers, so that on a GPU
// the per-list counters and cursors stay in registers (indexed by a runtime list number, they
// went to local memory: 304 and 384 B of stack per thread at sm_90; now none, 32 registers).
template <class Visit>
UPF_HD void for_each_neighbour(const GridView& g, const ListRequest& r, std::uint32_t s,
                               Visit& visit) {
  const Vec3 xi = g.sorted_x[s];
  auto candidate = [&](std::uint32_t u) {
    const Real dx = xi.x - g.sorted_x[u].x, dy = xi.y - g.sorted_x[u].y,
               dz = xi.z - g.sorted_x[u].z;
    const Real d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 < r.radius2) || u == s) return;
    visit(g.order[u], g.sorted_type[u]);
  };
  g.for_each_candidate(s, candidate);
}

struct CountStage {
  GridView g;
  ListRequest r;
  const ParticleType* type;
  const BodyId* body;
  std::uint32_t* count[kMaxLists];  // count[l][i + 1]
  UPF_HD void operator()(std::size_t i) const {
    std::uint32_t c0 = 0, c1 = 0, c2 = 0, c3 = 0;
    if (query_takes_particle(r.query, type, body, i)) {
      auto visit = [&](std::uint32_t, ParticleType t) {
        const std::uint32_t m = r.lists_of(t);
        c0 += m & 1u;
        c1 += (m >> 1) & 1u;
        c2 += (m >> 2) & 1u;
        c3 += (m >> 3) & 1u;
      };
      for_each_neighbour(g, r, g.slot_of[i], visit);
    }
    if (r.lists > 0) count[0][i + 1] = c0;
    if (r.lists > 1) count[1][i + 1] = c1;
    if (r.lists > 2) count[2][i + 1] = c2;
    if (r.lists > 3) count[3][i + 1] = c3;
  }
};

struct FillStage {
  GridView g;
  ListRequest r;
  const ParticleType* type;
  const BodyId* body;
  const std::uint32_t* offsets[kMaxLists];
  std::uint32_t* indices[kMaxLists];
  UPF_HD void operator()(std::size_t i) const {
    if (!query_takes_particle(r.query, type, body, i)) return;
    auto first = [&](int l) { return l < r.lists ? indices[l] + offsets[l][i] : nullptr; };
    std::uint32_t *n0 = first(0), *n1 = first(1), *n2 = first(2), *n3 = first(3);
    auto visit = [&](std::uint32_t j, ParticleType t) {
      const std::uint32_t m = r.lists_of(t);
      if (m == 0) return;
      if (m & 1u) *n0++ = j;
      if (m & 2u) *n1++ = j;
      if (m & 4u) *n2++ = j;
      if (m & 8u) *n3++ = j;
    };
    for_each_neighbour(g, r, g.slot_of[i], visit);
  }
};

}  // namespace grid_detail

template <class Backend>
class DeviceGrid {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  explicit DeviceGrid(Real cell_size) : cell_size_(cell_size) {}

  // Sorts particles [0, n) into cells. Positions must be finite.
  void build(const Vec3* x, const std::uint32_t* id, const ParticleType* type, std::size_t n) {
    using namespace grid_detail;
    n_ = n;
    const Real big = std::numeric_limits<Real>::max();
    const Vec3 lo =
        n ? thrust::reduce(Backend::policy(), x, x + n, Vec3{big, big, big}, Vec3Min{}) : Vec3{};
    origin_ = n ? Vec3{lo.x - cell_size_, lo.y - cell_size_, lo.z - cell_size_} : Vec3{};
    keys_.resize(n);
    for_each_index<Backend>(n, KeyStage{x, origin_, cell_size_, raw<std::uint64_t>(keys_)});

    // (key, id) order: by id first, then a stable sort by key. An id repeats only in periodic
    // images, a period (more than two cells) away from each other, so (key, id) is unique.
    order_.resize(n);
    thrust::sequence(Backend::policy(), order_.begin(), order_.end());
    scratch_ids_.resize(n);
    thrust::copy(Backend::policy(), id, id + n, scratch_ids_.begin());
    thrust::sort_by_key(Backend::policy(), scratch_ids_.begin(), scratch_ids_.end(),
                        order_.begin());
    sorted_keys_.resize(n);
    thrust::gather(Backend::policy(), order_.begin(), order_.end(), keys_.begin(),
                   sorted_keys_.begin());
    thrust::stable_sort_by_key(Backend::policy(), sorted_keys_.begin(), sorted_keys_.end(),
                               order_.begin());

    cell_begin_.resize(n + 1);
    const auto last =
        thrust::copy_if(Backend::policy(), thrust::counting_iterator<std::uint32_t>(0),
                        thrust::counting_iterator<std::uint32_t>(std::uint32_t(n)),
                        cell_begin_.begin(), KeyChanges{raw<std::uint64_t>(sorted_keys_)});
    cells_ = std::size_t(last - cell_begin_.begin());
    cell_begin_.resize(cells_ + 1);
    cell_begin_[cells_] = std::uint32_t(n);
    cell_key_.resize(cells_);
    thrust::gather(Backend::policy(), cell_begin_.begin(), cell_begin_.begin() + cells_,
                   sorted_keys_.begin(), cell_key_.begin());

    cell_of_slot_.resize(n);
    slot_of_.resize(n);
    for_each_index<Backend>(
        cells_, CellSlotsStage{raw<std::uint32_t>(cell_begin_), raw<std::uint32_t>(order_),
                               raw<std::uint32_t>(cell_of_slot_), raw<std::uint32_t>(slot_of_)});
    sorted_x_.resize(n);
    sorted_type_.resize(n);
    for_each_index<Backend>(
        n, SortedCopyStage{raw<std::uint32_t>(order_), x, type, raw<Vec3>(sorted_x_),
                           raw<ParticleType>(sorted_type_)});
    cell_neighbours_.resize(cells_ * 27);
    for_each_index<Backend>(cells_,
                            CellNeighboursStage{view(), raw<std::uint32_t>(cell_neighbours_)});
  }

  // Particle indices in (cell key, id) order: the locality order for reordering.
  const vector<std::uint32_t>& sorted_order() const { return order_; }
  std::size_t cell_count() const { return cells_; }
  std::size_t bytes() const {
    return bytes_of(keys_) + bytes_of(sorted_keys_) + bytes_of(cell_key_) + bytes_of(order_) +
           bytes_of(scratch_ids_) + bytes_of(cell_begin_) + bytes_of(cell_of_slot_) +
           bytes_of(slot_of_) + bytes_of(sorted_x_) + bytes_of(sorted_type_) +
           bytes_of(cell_neighbours_);
  }

  // For every particle whose type is in `query` (with kOfBodiesOnly, of a body: `body`), the
  // others within `radius` whose type is in targets[l], into outs[l] (up to kMaxLists), as
  // NeighbourGrid::find_neighbours.
  void find_neighbours(const ParticleType* type, const BodyId* body, TypeMask query,
                       const TypeMask* targets, int lists, Real radius,
                       DeviceNeighbourList<Backend>* const* outs) {
    using namespace grid_detail;
    ListRequest request{query, {}, lists, radius * radius, 0};
    for (int l = 0; l < lists; ++l) {
      request.target[l] = targets[l];
      for (int t = 0; t < kParticleTypeCount; ++t)
        if (type_in(targets[l], ParticleType(t))) request.lists_of_type |= 1u << (4 * t + l);
    }
    const GridView g = view();
    CountStage count{g, request, type, body, {}};
    for (int l = 0; l < lists; ++l) {
      outs[l]->offsets.resize(n_ + 1);
      outs[l]->offsets[0] = 0;
      count.count[l] = raw<std::uint32_t>(outs[l]->offsets);
    }
    for_each_index<Backend>(n_, count);
    FillStage fill{g, request, type, body, {}, {}};
    for (int l = 0; l < lists; ++l) {
      auto& offsets = outs[l]->offsets;
      thrust::inclusive_scan(Backend::policy(), offsets.begin(), offsets.end(), offsets.begin());
      outs[l]->indices.resize(std::size_t(offsets[n_]));
      fill.offsets[l] = raw<std::uint32_t>(offsets);
      fill.indices[l] = raw<std::uint32_t>(outs[l]->indices);
    }
    for_each_index<Backend>(n_, fill);
  }

 private:
  grid_detail::GridView view() const {
    return {raw<std::uint64_t>(cell_key_),
            raw<std::uint32_t>(cell_begin_),
            cells_,
            raw<std::uint32_t>(order_),
            raw<std::uint32_t>(slot_of_),
            raw<std::uint32_t>(cell_of_slot_),
            raw<Vec3>(sorted_x_),
            raw<ParticleType>(sorted_type_),
            raw<std::uint32_t>(cell_neighbours_)};
  }

  Real cell_size_;
  std::size_t n_ = 0, cells_ = 0;
  Vec3 origin_{};
  vector<std::uint64_t> keys_, sorted_keys_, cell_key_;
  vector<std::uint32_t> order_, scratch_ids_, cell_begin_, cell_of_slot_, slot_of_,
      cell_neighbours_;
  vector<Vec3> sorted_x_;
  vector<ParticleType> sorted_type_;
};

}  // namespace upf::device
