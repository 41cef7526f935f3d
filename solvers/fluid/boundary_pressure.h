// The pressure a wall pushes a fluid particle with, shared by PCISPH, WCSPH, IISPH and DFSPH
// (their parameter "wall_pressure", off by default; docs/boundary-pressure.md): frozen boundary
// particles (Akinci et al. 2012, "Versatile rigid-fluid coupling for incompressible SPH", ACM TOG
// 31(4)) that carry a pressure of their own, p_b, in the solvers' symmetric pair term with
// rho_b = rho_i:
//   a_i = -sum_b Psi_b (P_i + P_b) grad W_ib,  Psi_b = rho0_i V_b,  P = p / rho_i^2 (the solver's
//   pressure factor),
// where Akinci's eq. 10 has P_i alone. p_b is the wall pressure of Adami, Hu & Adams 2012 ("A
// generalized wall boundary condition for smoothed particle hydrodynamics", J. Comput. Phys. 231,
// eq. 27) for walls at rest: the fluid's pressure around i, Shepard-averaged, plus the hydrostatic
// difference between i and b, clamped at 0:
//   p_b = max(0, pbar_i + rho0 g . (x_b - x_i)),  pbar_i = sum_j W_ij p_j / sum_j W_ij (j = i too).
// The two parts are applied differently. The mirrored part, pbar_i, is this iteration's
// (mirrored_pressure_factor), so every pressure solver sees it; the hydrostatic part, which does
// not depend on this step's pressure, is an acceleration fixed for the step
// (boundary_hydrostatic_acceleration, added to a_other), which leaves the solvers' systems alone.
// Walls take no reactions; the frozen particles of static and kinematic bodies take both parts
// back (boundary_reactions.h), so their reported fluid force is what the fluid feels from them.
//
// Why (docs/boundary-pressure.md has the measurements). With P_i alone, a wall pushes its first
// fluid layer with half the force the fluid above pushes it down with: in a tank at rest that
// layer sank from its lattice height, 10 mm, to 6.1 mm above the floor, where the steeper kernel
// made up the difference, and read 1.72 times rho0 g d (PCISPH); a floor sensor reads that.
// Mirroring p_i itself (p_b = p_i) balances it, but makes the wall term indefinite: a particle a
// little too far from the wall is pushed further by its own pressure into denser fluid, and the
// implicit solvers at their usual tolerances (IISPH, DFSPH) and WCSPH kept the wall layer
// oscillating. The neighbourhood average takes i's own pressure in with its kernel weight only,
// and the layer settles with PCISPH (IISPH and DFSPH need eta 0.2 %). Without the hydrostatic
// part, the wall has no pressure gradient along it, and the fluid beside a side wall lacks half
// its support: it sinks along the walls and rises in the middle, a convection the walls keep
// driving (0.85 J in the tank after 4 s, against 0.001 J).
// Rigid bodies keep Akinci's single term: with p_b on them too (and its reactions), a cube of half
// the water's density floated with its centre 0.059 L above the waterline (bound 0.05 L); why is
// not known yet. The Müller et al. SPH solver keeps Akinci's single term too (sph_kernels.h says
// why).
#pragma once

#include "solvers/fluid/fluid_view.h"

namespace upf {

// The pressure factors P of the boundary terms, one struct per form.
// PCISPH: p_i / rho0_i^2.
// kPerDensitySquared: the factor is a pressure over a density squared (mirrored_pressure_factor).
struct PressureOverRestDensitySquared {
  static constexpr bool kPerDensitySquared = true;
  const Real* pressure;
  const Real* rest_density;
  const MaterialId* material;
  UPF_HD Real operator()(std::uint32_t i) const {
    const Real rho0 = rest_density[material[i]];
    return pressure[i] / (rho0 * rho0);
  }
};

// WCSPH, IISPH and the default pair term: p_i / rho_i^2, scaled (SPH's symmetrised force: 1/2).
struct PressureOverDensitySquared {
  static constexpr bool kPerDensitySquared = true;
  const Real* pressure;
  const Real* density;
  Real scale;
  UPF_HD Real operator()(std::uint32_t i) const {
    return scale * pressure[i] / (density[i] * density[i]);
  }
};

// A per-particle array that already is the factor (DFSPH's K).
struct FactorArray {
  static constexpr bool kPerDensitySquared = true;
  const Real* factor;
  UPF_HD Real operator()(std::uint32_t i) const { return factor[i]; }
};

// The pressures themselves (the floor of boundary_hydrostatic_acceleration).
struct PressureArray {
  static constexpr bool kPerDensitySquared = false;
  const Real* pressure;
  UPF_HD Real operator()(std::uint32_t i) const { return pressure[i]; }
};

// Shepard average of `factor` over particle i and its fluid neighbours: P_b of the frozen
// boundary particles next to i. 0 without the wall pressure or without boundary neighbours.
template <class Factor>
UPF_HD Real mirrored_pressure_factor(const FluidView& f, const Factor& factor, std::uint32_t i) {
  if (!f.wall_pressure || f.boundary.offsets[i] == f.boundary.offsets[i + 1]) return 0;
  const Vec3 xi = f.x[i];
  const Real w0 = f.kernel.value(Real(0));
  Real sum = w0 * factor(i), weight = w0;
  // With density contrast the factors p / rho^2 are each in the neighbour's own density: average
  // the pressures, in i's (rest densities standing for densities), or light liquid beside heavy
  // would read the heavy liquid's pressure (rho0_light / rho0_heavy)^2 times too low.
  const bool rescale = Factor::kPerDensitySquared && f.density_contrast;
  const Real rho0 = rescale ? f.rest_density[f.material[i]] : Real(1);
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    const Real w = f.kernel.value(xi - f.x[j]);
    Real pj = factor(j);
    if (rescale) {
      const Real ratio = f.rest_density[f.material[j]] / rho0;
      pj *= ratio * ratio;
    }
    sum += w * pj;
    weight += w;
  }
  return sum / weight;
}

// a_i from the boundary's pressure term: `boundary_gradient` = sum_b V_b grad W_ib over every
// boundary particle, `own` = P_i, `mirrored` = P_b (mirrored_pressure_factor), which acts through
// the frozen particles only.
UPF_HD inline Vec3 boundary_pressure_acceleration(const FluidView& f, const Vec3& boundary_gradient,
                                                  Real own, Real mirrored, std::uint32_t i) {
  const Real rho0 = f.rest_density[f.material[i]];
  Vec3 a = boundary_gradient * (-rho0 * own);
  if (mirrored == Real(0)) return a;
  Vec3 wall{};
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    if (f.type[b] != ParticleType::Frozen) continue;
    wall += f.kernel.gradient(f.x[i] - f.x[b]) * f.boundary_volume[b];
  }
  return a - wall * (rho0 * mirrored);
}

// The hydrostatic part of p_b (see the header), at the pressures `pressure` of the step's start:
//   a_i = -sum_b V_b (dp_b / rho0) grad W_ib,  dp_b = max(rho0 g . (x_b - x_i), -pbar_i),
// over the frozen b, so that the whole p_b stays >= 0 (no wall pulls the fluid). PCISPH's rho0^2
// in the pressure factor, for every solver: the part is rho0 g d across a few millimetres, and
// rho_i differs from rho0 by the solver's tolerance.
UPF_HD inline Vec3 boundary_hydrostatic_acceleration(const FluidView& f, const Real* pressure,
                                                     const Vec3& gravity, std::uint32_t i) {
  if (!f.wall_pressure || f.boundary.offsets[i] == f.boundary.offsets[i + 1]) return Vec3{};
  const Vec3 xi = f.x[i];
  const Real rho0 = f.rest_density[f.material[i]];
  const Real floor = -mirrored_pressure_factor(f, PressureArray{pressure}, i);
  Vec3 a{};
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    if (f.type[b] != ParticleType::Frozen) continue;
    const Real extra = rho0 * dot(gravity, f.x[b] - xi);
    const Real dp = extra > floor ? extra : floor;
    a -= f.kernel.gradient(xi - f.x[b]) * (f.boundary_volume[b] * dp);
  }
  return a / rho0;
}

}  // namespace upf
