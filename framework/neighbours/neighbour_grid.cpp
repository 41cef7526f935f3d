#include "framework/neighbours/neighbour_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <omp.h>

#include "framework/neighbours/chunked_sort.h"
#include "framework/neighbours/morton.h"
#include "framework/neighbours/select_within.h"

namespace upf {

NeighbourGrid::NeighbourGrid(Real cell_size) : cell_size_(cell_size) {}

void NeighbourGrid::cell_coords(const Vec3& x, std::uint32_t c[3]) const {
  for (int a = 0; a < 3; ++a) {
    // Far-away particles are clamped into the last cell: lists stay exact (distances are checked),
    // only slower, and the instability check stops such runs long before.
    // In double: x - origin in float could round a particle into the cell after next when the
    // origin is far away, and a neighbour closer than the radius would be missed.
    const double cell = std::floor((double(x[a]) - double(origin_[a])) / double(cell_size_));
    c[a] = static_cast<std::uint32_t>(std::clamp(cell, 0.0, double(kMortonAxisMax - 1)));
  }
}

std::uint64_t NeighbourGrid::key_of(const Vec3& x) const {
  std::uint32_t c[3];
  cell_coords(x, c);
  return morton_key(c[0], c[1], c[2]);
}

void NeighbourGrid::build(const Particles& particles, const CpuExecutor& exec) {
  const std::size_t n = particles.size();
  Real lo[3] = {std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max(),
                std::numeric_limits<Real>::max()};
  const Vec3* x = particles.position.data();
  const std::int64_t count = static_cast<std::int64_t>(n);
  Real lx = lo[0], ly = lo[1], lz = lo[2];
  Real hx = -lo[0], hy = -lo[1], hz = -lo[2];
#pragma omp parallel for schedule(static) num_threads(exec.threads()) reduction(min           \
                                                                                : lx, ly, lz) \
    reduction(max                                                                             \
              : hx, hy, hz)
  for (std::int64_t i = 0; i < count; ++i) {
    lx = std::min(lx, x[i].x);
    ly = std::min(ly, x[i].y);
    lz = std::min(lz, x[i].z);
    hx = std::max(hx, x[i].x);
    hy = std::max(hy, x[i].y);
    hz = std::max(hz, x[i].z);
  }
  // Across ranks the origin is global (the exact minimum over ranks): cells, and with them the
  // order of every neighbour list, are then those of one rank.
  bool any = n > 0;
  if (const RankCollectives* ranks = exec.collectives()) {
    lx = Real(ranks->min(double(lx)));
    ly = Real(ranks->min(double(ly)));
    lz = Real(ranks->min(double(lz)));
    any = lx != std::numeric_limits<Real>::max();
  }
  // One empty cell below the lowest particle, so that "cell - 1" never wraps.
  origin_ = any ? Vec3{lx - cell_size_, ly - cell_size_, lz - cell_size_} : Vec3{};

  keys_.resize(n);
  exec.for_each_index(n, [&](std::size_t i) { keys_[i] = key_of(x[i]); });

  // Start from id order, then a stable sort by key gives (key, id) order.
  const ParticleId id_bound = particles.id_bound();
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  if (particles.ghost_count() == 0) {
    // Ids are unique: each particle writes its own slot of an id-indexed table, and the table's
    // filled slots in id order are the particles in id order.
    sort_scratch_.resize(id_bound);
    exec.for_each_index(id_bound, [&](std::size_t d) { sort_scratch_[d] = kNone; });
    const ParticleId* id = particles.id.data();
    exec.for_each_index(n, [&](std::size_t i) { sort_scratch_[id[i]] = std::uint32_t(i); });
    chunked_select(
        exec, id_bound, [&](std::size_t d) { return sort_scratch_[d] != kNone; }, sorted_);
    exec.for_each_index(n, [&](std::size_t s) { sorted_[s] = sort_scratch_[sorted_[s]]; });
  } else {
    // Ghosts may repeat ids (a periodic image has its particle's id, in another cell): a
    // counting sort by id instead, stable in the index.
    sort_scratch_.assign(std::size_t(id_bound) + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++sort_scratch_[particles.id[i] + 1];
    for (std::size_t d = 1; d < sort_scratch_.size(); ++d) sort_scratch_[d] += sort_scratch_[d - 1];
    sorted_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      sorted_[sort_scratch_[particles.id[i]]++] = std::uint32_t(i);
  }
  radix_sort_by_key(exec, keys_.data(), sorted_, sort_scratch_);

  // A cell begins where the key changes.
  chunked_select(
      exec, n, [&](std::size_t s) { return s == 0 || keys_[sorted_[s]] != keys_[sorted_[s - 1]]; },
      cell_begin_);
  cell_keys_.resize(cell_begin_.size());
  exec.for_each_index(cell_keys_.size(),
                      [&](std::size_t c) { cell_keys_[c] = keys_[sorted_[cell_begin_[c]]]; });
  cell_begin_.push_back(std::uint32_t(n));
  // A dense cell table over the bounding box when it is not much larger than the particle count
  // (tanks, blocks): O(1) cell lookups. Sparse clouds fall back to binary search of the keys.
  dense_.clear();
  if (n) {
    const Vec3 hi{hx, hy, hz};
    double cells = 1;
    for (int a = 0; a < 3; ++a) {
      std::uint32_t c[3];
      cell_coords(hi, c);
      dims_[a] = c[a] + 2;  // one empty cell above the highest particle too
      cells *= double(dims_[a]);
    }
    if (cells <= 8.0 * double(n) + 4096.0) {
      dense_.assign(std::size_t(cells), 0);
      // Every cell writes its own entry.
      exec.for_each_index(cell_keys_.size(), [&](std::size_t c) {
        const std::uint64_t k = cell_keys_[c];
        const std::size_t linear =
            compact_bits_3d(k) +
            std::size_t(dims_[0]) *
                (compact_bits_3d(k >> 1) + std::size_t(dims_[1]) * compact_bits_3d(k >> 2));
        dense_[linear] = std::uint32_t(c + 1);
      });
    }
  }
  sorted_x_.resize(n);
  sorted_type_.resize(n);
  exec.for_each_index(n, [&](std::size_t s) {
    sorted_x_[s] = x[sorted_[s]];
    sorted_type_[s] = particles.type[sorted_[s]];
  });
}

void NeighbourGrid::CandidateBuffer::reserve(std::size_t m) {
  if (x.size() >= m + 3) return;  // select_within stores groups of four
  x.resize(m + 3);
  y.resize(m + 3);
  z.resize(m + 3);
  d2.resize(m + 3);
  particle.resize(m + 3);
  hit.resize(m + 3);
}

void NeighbourGrid::gather(const CellRange* ranges, int found, const std::vector<TypeMask>& targets,
                           CandidateBuffer* buffers, std::size_t* counts) const {
  std::size_t m = 0;
  for (int c = 0; c < found; ++c) m += ranges[c].end - ranges[c].begin;
  const std::size_t lists = targets.size();
  for (std::size_t l = 0; l < lists; ++l) buffers[l].reserve(m);
  // One pass per list (one pass filling all lists was slower): every candidate is written, and
  // the count advances only for a target type, with no branch on the type, which alternates at
  // random beside a wall.
  for (std::size_t l = 0; l < lists; ++l) {
    CandidateBuffer& b = buffers[l];
    const TypeMask target = targets[l];
    std::size_t k = 0;
    for (int c = 0; c < found; ++c)
      for (std::uint32_t u = ranges[c].begin; u < ranges[c].end; ++u) {
        b.x[k] = sorted_x_[u].x;
        b.y[k] = sorted_x_[u].y;
        b.z[k] = sorted_x_[u].z;
        b.particle[k] = sorted_[u];
        k += in_mask(target, sorted_type_[u]);
      }
    counts[l] = k;
  }
}

int NeighbourGrid::neighbour_cells(std::size_t cell, CellRange ranges[27]) const {
  std::uint32_t c[3];
  const std::uint64_t key = cell_keys_[cell];
  c[0] = compact_bits_3d(key);
  c[1] = compact_bits_3d(key >> 1);
  c[2] = compact_bits_3d(key >> 2);
  int found = 0;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::int64_t nx = std::int64_t(c[0]) + dx, ny = std::int64_t(c[1]) + dy,
                           nz = std::int64_t(c[2]) + dz;
        if (nx < 0 || ny < 0 || nz < 0 || nx > kMortonAxisMax || ny > kMortonAxisMax ||
            nz > kMortonAxisMax)
          continue;
        std::size_t j;
        if (!dense_.empty()) {
          if (nx >= dims_[0] || ny >= dims_[1] || nz >= dims_[2]) continue;
          const std::uint32_t slot =
              dense_[std::size_t(nx) +
                     std::size_t(dims_[0]) *
                         (std::size_t(ny) + std::size_t(dims_[1]) * std::size_t(nz))];
          if (slot == 0) continue;
          j = slot - 1;
        } else {
          const std::uint64_t k =
              morton_key(std::uint32_t(nx), std::uint32_t(ny), std::uint32_t(nz));
          auto it = std::lower_bound(cell_keys_.begin(), cell_keys_.end(), k);
          if (it == cell_keys_.end() || *it != k) continue;
          j = std::size_t(it - cell_keys_.begin());
        }
        ranges[found++] = {cell_begin_[j], cell_begin_[j + 1]};
      }
  return found;
}

void NeighbourGrid::find_neighbours(const Particles& particles, TypeMask query, TypeMask target,
                                    Real radius, const CpuExecutor& exec,
                                    NeighbourList& out) const {
  find_neighbours(particles, query, std::vector<TypeMask>{target}, radius, exec,
                  std::vector<NeighbourList*>{&out});
}

void NeighbourGrid::find_neighbours(const Particles& particles, TypeMask query,
                                    const std::vector<TypeMask>& targets, Real radius,
                                    const CpuExecutor& exec,
                                    const std::vector<NeighbourList*>& outs) const {
  const std::size_t n = particles.size();
  const std::size_t lists = targets.size();
  const Real r2 = radius * radius;
  const BodyId* body = particles.body.data();
  // Whether sorted slot s is a query particle (kOfBodiesOnly: only those of a body).
  auto takes = [&](std::uint32_t s) {
    return query_takes(query, sorted_type_[s],
                       (query & kOfBodiesOnly) != 0 && body[sorted_[s]] != kNoBody);
  };

  // One pass: each thread appends its particles' neighbours to its own buffers and records where
  // they are; the final CSR arrays are then assembled by copying. A particle's neighbours are
  // found by one thread in a fixed order, so the result does not depend on the thread count.
  const int threads = exec.threads();
  // Scratch kept between calls: no allocation (and no page faults) in the steady state.
  if (lists > kMaxLists) throw std::invalid_argument("find_neighbours: too many target lists");
  auto& per_thread = scratch_.threads;
  per_thread.resize(static_cast<std::size_t>(threads));
  for (auto& ts : per_thread)
    for (std::size_t l = 0; l < lists; ++l) {
      ts.used[l] = 0;
      ts.segments[l].clear();
    }
  for (NeighbourList* out : outs) out->offsets.assign(n + 1, 0);

  const std::int64_t cells = std::int64_t(cell_keys_.size());
#pragma omp parallel num_threads(threads)
  {
    ThreadScratch& mine = per_thread[std::size_t(omp_get_thread_num())];
    auto& my_buffers = mine.buffers;
    auto& my_segments = mine.segments;
#pragma omp for schedule(dynamic, 32)
    for (std::int64_t cell = 0; cell < cells; ++cell) {
      const std::uint32_t first = cell_begin_[std::size_t(cell)];
      const std::uint32_t last = cell_begin_[std::size_t(cell) + 1];
      bool any_query = false;
      for (std::uint32_t s = first; s < last; ++s) any_query = any_query || takes(s);
      if (!any_query) continue;
      CellRange ranges[27];
      const int found = neighbour_cells(std::size_t(cell), ranges);
      // The candidates of the 27 cells, gathered once for all particles of this cell into
      // coordinate arrays, one set per list: the distance loop below then vectorises, and the
      // hits are picked out without a branch per candidate (select_within.h).
      std::size_t m[kMaxLists];
      gather(ranges, found, targets, mine.candidates, m);
      for (std::uint32_t s = first; s < last; ++s) {
        if (!takes(s)) continue;
        const std::uint32_t i = sorted_[s];
        const Real xi = sorted_x_[s].x, yi = sorted_x_[s].y, zi = sorted_x_[s].z;
        for (std::size_t l = 0; l < lists; ++l) {
          CandidateBuffer& cand = mine.candidates[l];
          my_segments[l].push_back({i, std::uint32_t(mine.used[l])});
          const Real* cx = cand.x.data();
          const Real* cy = cand.y.data();
          const Real* cz = cand.z.data();
          Real* d2 = cand.d2.data();
          for (std::size_t k = 0; k < m[l]; ++k) {
            const Real dx = xi - cx[k], dy = yi - cy[k], dz = zi - cz[k];
            d2[k] = dx * dx + dy * dy + dz * dz;
          }
          const std::size_t hits = select_within(d2, m[l], r2, cand.hit.data());
          // The particle itself is a candidate of its own list: written, and not counted.
          // Grown, never shrunk nor cleared: resizing per particle zeroed memory it then wrote.
          auto& buffer = my_buffers[l];
          if (buffer.size() < mine.used[l] + hits)
            buffer.resize(std::max(2 * buffer.size(), mine.used[l] + hits));
          std::uint32_t* out = buffer.data() + mine.used[l];
          std::size_t written = 0;
          for (std::size_t h = 0; h < hits; ++h) {
            const std::uint32_t j = cand.particle[cand.hit[h]];
            out[written] = j;
            written += j != i;
          }
          mine.used[l] += written;
        }
      }
    }
  }

  for (std::size_t l = 0; l < lists; ++l) {
    std::uint32_t* offsets = outs[l]->offsets.data();
    for (int t = 0; t < threads; ++t) {
      const auto& seg = per_thread[std::size_t(t)].segments[l];
      const auto used = std::uint32_t(per_thread[std::size_t(t)].used[l]);
      for (std::size_t k = 0; k < seg.size(); ++k) {
        const std::uint32_t end = k + 1 < seg.size() ? seg[k + 1].begin : used;
        offsets[seg[k].particle + 1] = end - seg[k].begin;
      }
    }
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    outs[l]->indices.resize(offsets[n]);
    std::uint32_t* indices = outs[l]->indices.data();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int t = 0; t < threads; ++t) {
      const auto& seg = per_thread[std::size_t(t)].segments[l];
      const auto& buf = per_thread[std::size_t(t)].buffers[l];
      const auto used = std::uint32_t(per_thread[std::size_t(t)].used[l]);
      for (std::size_t k = 0; k < seg.size(); ++k) {
        const std::uint32_t end = k + 1 < seg.size() ? seg[k + 1].begin : used;
        std::copy(buf.begin() + seg[k].begin, buf.begin() + end,
                  indices + offsets[seg[k].particle]);
      }
    }
  }
}

}  // namespace upf
