// Uniform-grid neighbour search with Morton-ordered cells and a counting (radix) sort.
//
// The grid's cell edge equals the search radius, so a particle's neighbours lie in the 27 cells
// around it. Particles are sorted by (cell Morton key, stable id); neighbour lists list the 27
// cells in a fixed order and the particles of a cell in id order. A list therefore depends only on
// positions and ids, never on where particles sit in memory: reordering particles for locality
// cannot change a single bit of a simulation.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/particle_type.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf {

class NeighbourGrid {
 public:
  explicit NeighbourGrid(Real cell_size);

  Real cell_size() const { return cell_size_; }

  // Sorts all particles into cells. Positions must be finite.
  void build(const Particles& particles, const CpuExecutor& exec);

  // Particle indices in (cell key, id) order: the locality order used for reordering.
  const std::vector<std::uint32_t>& sorted_order() const { return sorted_; }
  std::size_t cell_count() const { return cell_keys_.size(); }

  // Lists, for every particle whose type is in `query`, the other particles whose type is in
  // `target` within `radius` (<= cell size), excluding the particle itself.
  void find_neighbours(const Particles& particles, TypeMask query, TypeMask target, Real radius,
                       const CpuExecutor& exec, NeighbourList& out) const;

  // The same for several target sets at once (one list each), in one scan of the candidates:
  // what the world does every step for (liquid -> liquid, liquid -> boundary).
  void find_neighbours(const Particles& particles, TypeMask query,
                       const std::vector<TypeMask>& targets, Real radius, const CpuExecutor& exec,
                       const std::vector<NeighbourList*>& outs) const;

 private:
  struct CellRange {
    std::uint32_t begin, end;
  };
  std::uint64_t key_of(const Vec3& x) const;
  void cell_coords(const Vec3& x, std::uint32_t c[3]) const;
  // The 27 neighbour cell ranges of the cell holding sorted slot `cell`, in a fixed order.
  int neighbour_cells(std::size_t cell, CellRange ranges[27]) const;

  Real cell_size_;
  Vec3 origin_{};
  std::vector<std::uint64_t> keys_;    // per particle (memory order)
  std::vector<std::uint32_t> sorted_;  // particle indices in (key, id) order
  std::vector<std::uint32_t> sort_scratch_;
  std::vector<std::uint64_t> cell_keys_;   // distinct keys, ascending
  std::vector<std::uint32_t> cell_begin_;  // into sorted_, size cell_count()+1
  // Positions and types gathered in sorted order, so candidate scans read contiguous memory.
  std::vector<Vec3> sorted_x_;
  std::vector<std::uint32_t> dense_;  // cell slot + 1 by linear cell index; empty when sparse
  std::int64_t dims_[3] = {0, 0, 0};
  // Per-thread result buffers of find_neighbours, reused from call to call.
  struct Segment {
    std::uint32_t particle, begin;
  };
  // The candidates of one cell's 27 neighbour cells whose type is in one list's target set, as
  // coordinate arrays (one per thread and list), in the cells' fixed order and id order within a
  // cell: a list's hits then come out in its order with no type test per hit.
  struct CandidateBuffer {
    std::vector<Real> x, y, z, d2;
    std::vector<std::uint32_t> particle, hit;  // particle index of each candidate; hits
    void reserve(std::size_t m);
  };
  // Fills the buffers of the target sets from the cell ranges; each list's candidate count goes
  // into `counts`.
  void gather(const CellRange* ranges, int found, const std::vector<TypeMask>& targets,
              CandidateBuffer* buffers, std::size_t* counts) const;
  // One thread's result buffers, on cache lines of its own: threads appending to vectors whose
  // headers shared a line slowed the whole scan down (false sharing).
  static constexpr std::size_t kMaxLists = 4;
  struct alignas(64) ThreadScratch {
    std::vector<std::uint32_t> buffers[kMaxLists];  // neighbour indices, by list
    std::size_t used[kMaxLists] = {};               // the filled front of each buffer
    std::vector<Segment> segments[kMaxLists];       // where each particle's run starts, by list
    CandidateBuffer candidates[kMaxLists];
  };
  struct Scratch {
    std::vector<ThreadScratch> threads;
  };
  mutable Scratch scratch_;
  std::vector<ParticleType> sorted_type_;
};

}  // namespace upf
