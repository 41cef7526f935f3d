// SPH: Müller, Charypar & Gross 2003, "Particle-based fluid simulation for interactive
// applications" (Proc. ACM SIGGRAPH/Eurographics Symposium on Computer Animation, SCA 2003).
//
// One pressure evaluation per step (SolverStats::iterations = 1): the pressure follows from the
// density through the paper's state equation (eq. 12)
//   p_i = k (rho_i - rho0),
// and its force (eq. 10) is the symmetrised
//   f_i = -sum_j m_j (p_i + p_j) / (2 rho_j) grad W(x_ij),   a_i = f_i / rho_i (eq. 8),
// with Akinci et al. 2012 boundaries (sph_kernels.h). In the bulk sum_j m_j p_i / rho_j grad W_ij
// is about zero, so the force is half the SPH pressure gradient: water at rest holds
// p = 2 rho0 g d, compresses by 2 g d / k, and its pressure waves travel at sqrt(k / 2).
//
// Stiffness: `stiffness` = 0 (the default) takes k = 2 c^2 with WCSPH's automatic
// c = 10 sqrt(2 g H), so both weakly compressible solvers run at the same effective speed of sound
// and compress alike (about 1 %). At a fixed k = 1000 m^2/s^2 the dam break's surge (4-5 m/s)
// pressed its front 20-30 % into the far wall and through it, and k = 2000 lost a run-up jet
// through the lid; the automatic 3139 (4000 too) kept every particle in. The step obeys the CFL
// condition on sqrt(k) + |v|max, the speed of sound of the state equation (an upper bound on the
// effective sqrt(k / 2)).
//
// Kernels (sph_kernel_sets.h): the cubic spline of the other fluid solvers by default, or the
// paper's (poly6 density, spiky pressure gradient, viscosity-kernel Laplacian) with
// `cubic_spline` = 0. The paper's set is not stable on its own at a stiffness that keeps water
// within about 1 %: poly6 is flat at r = 0, so close pairs barely raise the density while the spiky
// gradient pushes them hard; the force is not the gradient of the density's energy, and the
// hydrostatic tank heats up (5 cm spacing, default k: kinetic energy 0 -> 250 J in 1.1 s, 980 J
// in 1.8 s; at 4 cm and k = 1000 likewise with a quarter of the time step, and still 20 J in 1 s
// with the poly6 gradient instead of the spiky one). The paper ran soft gases with strong
// viscosity; here mu = 20 Pa s keeps the tank near rest (0.1 J), 3.5 does not (130 J at 2 s).
// With H = 2 spacings, poly6 sums to 1.0098 / spacing^3 over the initial lattice (the cubic spline
// to 0.99997): water at rest would read 1 % dense and push itself apart, so the poly6 density is
// scaled by the inverse of its lattice sum.
//
// Negative pressures are clamped to zero, as in PCISPH: at the free surface the density sum
// misses neighbours and would turn into suction that clumps surface particles (tensile
// instability); the clamp only lets the fluid resist compression.
//
// Non-pressure forces are the shared ones (gravity, the material's viscosity nu): with the
// default mu = 0 a comparison with PCISPH or WCSPH isolates the pressure solver. mu > 0 adds the
// paper's viscosity force (eq. 14), f_i = mu sum_j m_j (v_j - v_i) / rho_j lap W(x_ij), between
// liquid particles.
#pragma once

#include <vector>

#include "framework/params/param_binding.h"
#include "solvers/fluid/equation_of_state_solver.h"
#include "solvers/sph/sph_steps.h"

namespace upf {

struct SphParams {
  double stiffness = 0;  // m^2/s^2; 0: automatic
  double viscosity = 0;  // Pa s, added to the material's
  bool cubic_spline = true;
};

class SphSolver final : public EquationOfStateSolver {
 public:
  SphSolver(const SphParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override { return "sph"; }
  Real max_time_step(const World& world) const override;

  static ParamBinding<SphParams> param_binding();
  // The stiffness in use: `stiffness`, or 2 (10 sqrt(2 g H))^2 when it is 0. Set by prepare().
  Real stiffness() const { return stiffness_; }
  Real paper_viscosity() const { return mu_; }
  // The kernels in use (sph_steps.h), for this solver's step and the device pipeline (device/).
  SphKernelChoice kernel_choice(Real support_radius) const;
  // 1 / (spacing^3 sum W_poly6) over the template lattice neighbourhood: the factor that makes the
  // poly6 density of a lattice-sampled fluid equal rho0.
  static Real poly6_lattice_scale(Real spacing, Real support_radius);

 private:
  void prepare_method(World& world) override;
  // The paper's kernels' density (when they are chosen) and the paper's viscosity (mu > 0).
  void add_own_non_pressure(const World& world, const FluidView& f, Real* density) override;
  // p = k (rho - rho0) and the paper's pressure acceleration.
  void compute_pressure(const World& world, const FluidView& f, const Real* density,
                        Real* pressure) override;
  void add_reactions(World& world, const FluidView& f, const Real* density,
                     const Real* pressure) const override;
  Real requested_stiffness_;  // [m^2/s^2] 0: automatic
  Real mu_;                   // [Pa s] the paper's dynamic viscosity
  bool cubic_spline_;
  Real stiffness_ = 0;  // [m^2/s^2] k in use
  Real poly6_scale_ = 1;
  Real max_viscosity_ = 0;  // [m^2/s] nu + mu / rho0, largest over the owned materials
};

}  // namespace upf
