// No-slip walls for the viscosity against boundary particles (Adami, Hu & Adams 2012, "A
// generalized wall boundary condition for smoothed particle hydrodynamics", J. Comput. Phys. 231,
// eq. 22-23): a wall or body particle b takes part in the viscous sum with the velocity
//   v~_b = 2 v_b - sum_i v_i W_ib / sum_i W_ib
// over its liquid neighbours i, the liquid's velocity extrapolated through the wall, so the
// liquid's velocity goes to the wall's at the wall's face. With the wall's own velocity instead
// (what fluid_forces.h used before), the liquid slipped: a shear wave between two walls decayed
// 12 % too slowly with the slip, and a wall particle outside the liquid's reach kept its own.
// Only with a liquid's boundary_viscosity > 0 (FluidSolverState asks for the list then).
//
// Free-slip walls (a boundary material's "free_slip": 1; the same paper's section 2.3, there
// with ghost velocities) take the liquid's own mean velocity along their surface and the no-slip
// one across it:
//   v~_b = vbar + n n . (2 v_b - 2 vbar),   vbar = sum_i v_i W_ib / sum_i W_ib,
// with n_b the wall's normal (framework/boundary/slip_normal.h), so a liquid sliding along the
// wall as a whole feels no friction there; its motion into and off the wall, and each particle's
// departure from its neighbours' mean, are damped. A jet on a plate showed why it matters: with
// walls that only push, the thin sheet's jitter normal to the plate is rectified, and the sheet
// left moving back towards the jet, 5 % of the jet's force too much (docs/emitters.md). Explicit
// viscosity only: the implicit solve would hold vbar at the step's start, and a stiff liquid
// could then not slide faster than it did (World::prepare refuses the pair).
// C++17: nvcc builds it.
#pragma once

#include "solvers/fluid/fluid_view.h"

namespace upf {

// The field FluidSolverState declares for the velocities (the device pipeline finds it by name).
inline constexpr const char* kWallVelocityField = "fluid.wall_velocity";

// Whether b is a free-slip wall, and then its normal.
UPF_HD inline bool free_slip_normal(const FluidView& f, std::uint32_t b, Vec3& n) {
  if (!f.slip_normal) return false;
  n = f.slip_normal[b];
  return squared_norm(n) > 0;
}

// Over all particles; only boundary particles have entries in `liquid_of_boundary`.
struct WallVelocityStage {
  FluidView f;
  NeighbourView liquid_of_boundary;  // boundary -> liquid
  Vec3* wall_velocity;               // out, per particle
  UPF_HD void operator()(std::uint32_t b) const {
    const std::uint32_t begin = liquid_of_boundary.offsets[b];
    const std::uint32_t end = liquid_of_boundary.offsets[b + 1];
    Vec3 sum{};
    Real weight = 0;
    const Vec3 xb = f.x[b];
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = liquid_of_boundary.indices[k];
      const Real w = f.kernel.value(xb - f.x[i]);
      sum += f.v[i] * w;
      weight += w;
    }
    if (!(weight > 0)) {
      wall_velocity[b] = f.v[b];
      return;
    }
    const Vec3 mean = sum / weight;
    const Vec3 no_slip = f.v[b] * Real(2) - mean;
    Vec3 n;
    wall_velocity[b] = free_slip_normal(f, b, n) ? mean + n * dot(n, no_slip - mean) : no_slip;
  }
};

// The velocity a boundary particle has in the viscous sums: the extrapolated one where the
// stage ran (f.wall_velocity), else its own.
UPF_HD inline Vec3 viscous_wall_velocity(const FluidView& f, std::uint32_t b) {
  return f.wall_velocity ? f.wall_velocity[b] : f.v[b];
}

}  // namespace upf
