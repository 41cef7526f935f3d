// An outlet's outflow buffer: a layer of liquid just upstream of a sink whose velocity along the
// outflow is imposed before every step, after the outflow buffer of Tafuni et al. 2018 ("A
// versatile algorithm for the treatment of open boundary conditions in SPH", Comput. Methods
// Appl. Mech. Eng. 342; DualSPHysics' outlets). Without it the liquid at a sink's face has
// nothing downstream: it is a free surface, so the liquid accelerates into the sink and draws
// the level down upstream of it (measured: a 14 % dip 5 cm before the outlet of a flat channel).
// With it the buffer's liquid leaves at the speed the flow arrives with, as a piston that
// retreats at that speed: the flow upstream sees liquid ahead of it, not a void.
//
// The speed is imposed (a number) or extrapolated from the liquid just upstream of the buffer
// with zero gradient along the outflow, as Tafuni's extrapolated outlet: the mean outflow speed of
// the liquid in a slab `reference` thick before the buffer, per cell of the cross-section (cells
// about 2 spacings wide), so a profile across the outlet carries through. Tafuni extrapolates at
// mirror points with a corrected kernel; the cell mean needs no neighbours outside the step and
// is summed in fixed point, so it is the same bits on any thread count and summed exactly over
// MPI ranks. Only the component along the outflow is set: gravity and the free surface act
// across it as anywhere else. The pressure is the solver's (Tafuni's outlet imposes or
// extrapolates it too); a speed that would flow back into the domain is held at 0.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "framework/core/real.h"
#include "framework/core/vec3.h"

namespace upf {

class Particles;
class RankCollectives;

struct OutflowBufferDesc {
  int axis = 0;  // the outflow goes along sign * e_axis
  double sign = 1;
  double face = 0;       // the sink's upstream face: where the buffer ends, along the axis
  double length = 0;     // how far upstream of the face the buffer reaches (m)
  double reference = 0;  // the thickness of the slab before the buffer the speed is taken from
  std::optional<double> speed;  // imposed (m/s); none: extrapolated
  // The cross-section: the two other axes, from `lo`, cut into `cells` of `cell` metres.
  std::array<int, 2> across{1, 2};
  std::array<double, 2> lo{0, 0}, cell{1, 1};
  std::array<int, 2> cells{1, 1};
};

class OutflowBuffer {
 public:
  explicit OutflowBuffer(OutflowBufferDesc desc);
  // Sets the outflow component of the velocity of every liquid particle in the buffer.
  void apply(Particles& particles, const RankCollectives* ranks);

 private:
  // The cross-section cell of `x`, if inside the section.
  std::optional<std::size_t> cell_of(const Vec3& x) const;
  // Upstream distance from the face along the outflow (negative upstream).
  double along(const Vec3& x) const;

  OutflowBufferDesc desc_;
  std::vector<std::int64_t> sums_;  // per cell: the speeds in fixed point, then the count
};

}  // namespace upf
