// What a world split over MPI ranks (framework/world/particle_domain.h) adds to the executor:
// every reduction becomes global and every particle stage is followed by a ghost refresh
// (DESIGN.md, "Beyond one machine").
//
// The refresh after each stage is what lets every solver run unchanged across ranks: a stage
// writes only its own particles and reads its neighbours' values written by earlier stages, so
// once the ghosts hold their owners' values after every stage, each owned particle sees exactly
// what it would see on one rank. Every rank runs the same stages in the same order (the control
// flow depends only on global reductions), so the refreshes pair up.
#pragma once

#include <cstddef>
#include <cstdint>

namespace upf {

class RankCollectives {
 public:
  virtual ~RankCollectives() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // In place over all ranks: exact integer sums, exact extremes.
  virtual void sum(std::int64_t* values, std::size_t count) const = 0;
  virtual double max(double local) const = 0;
  virtual double min(double local) const = 0;
  // A sum of doubles over ranks, in rank order: for metrics only, never for control flow.
  virtual double sum_of_doubles(double local) const = 0;
  // Ghosts take their owners' current values (every particle array and coupling array).
  virtual void refresh_ghosts() const = 0;

  std::int64_t sum(std::int64_t local) const {
    sum(&local, 1);
    return local;
  }
};

}  // namespace upf
