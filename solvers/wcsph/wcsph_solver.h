// WCSPH: Becker & Teschner 2007, "Weakly compressible SPH for free surface flows" (Proc. ACM
// SIGGRAPH/Eurographics Symposium on Computer Animation, SCA 2007).
//
// One pressure evaluation per step (SolverStats::iterations = 1): the pressure follows from the
// density through the Tait equation
//   p_i = B ((rho_i / rho0)^7 - 1),  B = rho0 c^2 / 7,
// and accelerates with the paper's symmetric form
//   a_i = -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad W_ij,
// cubic spline kernel, Akinci et al. 2012 boundaries (wcsph_kernels.h). The speed of sound c sets
// the compression: density varies by about (v / c)^2, so the paper picks c from the largest
// expected speed, c = 10 v for about 1 %. With `sound_speed` = 0 (the default) c = 10 sqrt(2 g H),
// H the height of the initial liquid (sound_speed.h). The step obeys the CFL condition on the
// speed of sound, dt <= cfl * h / (c + |v|max), h = H_support / 2 = the particle spacing.
//
// The paper's artificial viscosity (after Monaghan 1992, acting only between approaching
// particles) damps the noise of a stiff state equation:
//   a_i = -sum_j m_j Pi_ij grad W_ij,
//   Pi_ij = -nu min(v_ij . x_ij, 0) / (|x_ij|^2 + 0.01 h^2),  nu = 2 alpha h c / (rho_i + rho_j).
// It adds to the shared non-pressure forces (gravity, the material's viscosity); alpha = 0 leaves
// only those, so a comparison isolates the pressure solver. The default 0.1 is at the low end of
// the paper's range (0.08 to 0.5): the shared viscosity already damps, and the dam break keeps
// every particle in the tank even at alpha = 0. It barely damps the column's slowest acoustic
// mode: the hydrostatic tank, started at rho0, keeps ringing (period about 4 H / c).
//
// Negative pressures are clamped to zero, as in PCISPH: at the free surface the density sum
// misses neighbours and (rho / rho0)^7 - 1 < 0 would pull surface particles into clumps (tensile
// instability); the fluid only resists compression.
#pragma once

#include <vector>

#include "framework/params/param_binding.h"
#include "solvers/fluid/equation_of_state_solver.h"

namespace upf {

struct WcsphParams {
  double sound_speed = 0;  // m/s; 0: automatic
  double alpha = 0;        // artificial viscosity
  double cfl = 0;
  double wall_pressure = 0;  // boundary_pressure.h: 1 on, 0 Akinci's term alone
};

class WcsphSolver final : public EquationOfStateSolver {
 public:
  WcsphSolver(const WcsphParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override { return "wcsph"; }
  Real max_time_step(const World& world) const override;

  static ParamBinding<WcsphParams> param_binding();
  // The speed of sound in use: `sound_speed`, or 10 sqrt(2 g H) when it is 0. Set by prepare().
  Real sound_speed() const { return sound_speed_; }
  // 2 alpha h c of the artificial viscosity (h = support / 2), 0 without it; per material
  // B = rho0 c^2 / 7 of the Tait equation. For the device pipeline too (device/).
  Real artificial_viscosity_factor(Real support_radius) const;
  const std::vector<Real>& tait_factors() const { return tait_factor_; }

 private:
  void prepare_method(World& world) override;
  // The artificial viscosity.
  void add_own_non_pressure(const World& world, const FluidView& f, Real* density) override;
  // Tait pressures and the symmetric pressure acceleration.
  void compute_pressure(const World& world, const FluidView& f, const Real* density,
                        Real* pressure) override;

  Real requested_sound_speed_;  // [m/s] 0: automatic
  Real alpha_;
  Real cfl_;
  Real sound_speed_ = 0;           // [m/s] c
  std::vector<Real> tait_factor_;  // [Pa] per material: B = rho0 c^2 / 7
};

}  // namespace upf
