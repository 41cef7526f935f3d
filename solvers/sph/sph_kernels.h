// The per-particle functions of SPH (Müller, Charypar & Gross 2003, "Particle-based fluid
// simulation for interactive applications", SCA 2003), written once for host and device and
// generic over the kernel set (sph_kernel_sets.h). Boundaries follow Akinci et al. 2012 with the
// kernel of the fluid term they belong to.
#pragma once

#include "solvers/fluid/fluid_view.h"

namespace upf {

// Density (paper eq. 3 with the density kernel) plus Akinci's boundary term, times `scale`:
//   rho_i = scale (sum_j m_j W_ij + sum_b Psi_b W_ib),  Psi_b = rho0_i V_b, j including i.
// `scale` corrects the kernel's sum over the initial lattice to 1 (sph_solver.h).
template <class Kernels>
UPF_HD Real sph_density(const FluidView& f, const Kernels& w, Real scale, std::uint32_t i) {
  const Vec3 xi = f.x[i];
  Real rho = f.mass[i] * w.density(Vec3{});
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    rho += f.mass[j] * w.density(xi - f.x[j]);
  }
  Real boundary = 0;
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    boundary += f.boundary_volume[b] * w.density(xi - f.x[b]);
  }
  return scale * (rho + f.rest_density[f.material[i]] * boundary);
}

// The paper's state equation (eq. 12), p = k (rho - rho0), clamped at zero: see sph_solver.h.
UPF_HD inline Real sph_pressure(Real rho, Real rest_density, Real stiffness) {
  const Real p = stiffness * (rho - rest_density);
  return p > 0 ? p : Real(0);
}

// Pressure acceleration, the paper's symmetrised force (eq. 10) divided by rho_i (eq. 8):
//   a_i = -(1/rho_i) sum_j m_j (p_i + p_j) / (2 rho_j) grad W_ij
//         -sum_b Psi_b p_i / (2 rho_i^2) grad W_ib       (Akinci et al. 2012, eq. 10)
// Akinci's boundary term is the own-pressure part of the fluid pair term with rho_b = rho_i:
// p_i / rho_i^2 for PCISPH's and WCSPH's pair term p_i / rho_i^2 + p_j / rho_j^2, and
// p_i / (2 rho_i^2) for the paper's (p_i + p_j) / (2 rho_i rho_j). The full p_i / rho_i^2 made the
// walls twice as stiff as the fluid they stand in for; the wall forces then did net work and
// the hydrostatic tank heated up without bound (kinetic energy 0 -> 77 J in 1 s, cubic spline,
// 4 cm spacing).
template <class Kernels>
UPF_HD Vec3 sph_pressure_acceleration(const FluidView& f, const Kernels& w, const Real* density,
                                      const Real* pressure, std::uint32_t i) {
  const Vec3 xi = f.x[i];
  const Real pi = pressure[i];
  Vec3 fluid{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    fluid -= w.pressure_gradient(xi - f.x[j]) *
             (f.mass[j] * (pi + pressure[j]) / (Real(2) * density[j]));
  }
  Vec3 boundary{};
  for (std::uint32_t k = f.boundary.offsets[i]; k < f.boundary.offsets[i + 1]; ++k) {
    const std::uint32_t b = f.boundary.indices[k];
    boundary += w.pressure_gradient(xi - f.x[b]) * f.boundary_volume[b];
  }
  const Real rho = density[i];
  const Real rho0 = f.rest_density[f.material[i]];
  return fluid / rho - boundary * (rho0 * pi / (Real(2) * rho * rho));
}

// The paper's viscosity (eq. 14) divided by rho_i, with a dynamic viscosity mu [Pa s]:
//   a_i = (mu / rho_i) sum_j m_j (v_j - v_i) / rho_j lap W_ij
// Between liquid particles only: wall friction stays the shared boundary_viscosity.
template <class Kernels>
UPF_HD Vec3 sph_viscosity_acceleration(const FluidView& f, const Kernels& w, const Real* density,
                                       Real mu, std::uint32_t i) {
  const Vec3 xi = f.x[i];
  const Vec3 vi = f.v[i];
  Vec3 a{};
  for (std::uint32_t k = f.fluid.offsets[i]; k < f.fluid.offsets[i + 1]; ++k) {
    const std::uint32_t j = f.fluid.indices[k];
    a += (f.v[j] - vi) * (f.mass[j] / density[j] * w.viscosity_laplacian(xi - f.x[j]));
  }
  return a * (mu / density[i]);
}

// The stages of SPH, for a kernel set of sph_kernel_sets.h.
template <class Kernels>
struct SphDensityStage {
  FluidView f;
  Kernels kernels;
  Real scale;
  Real* density;
  UPF_HD void operator()(std::uint32_t i) const { density[i] = sph_density(f, kernels, scale, i); }
};

template <class Kernels>
struct SphViscosityStage {
  FluidView f;
  Kernels kernels;
  const Real* density;
  Real mu;
  Vec3* a_other;
  UPF_HD void operator()(std::uint32_t i) const {
    a_other[i] += sph_viscosity_acceleration(f, kernels, density, mu, i);
  }
};

struct SphPressureStage {
  FluidView f;
  const Real* density;
  Real stiffness;
  Real* pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    pressure[i] = sph_pressure(density[i], f.rest_density[f.material[i]], stiffness);
  }
};

template <class Kernels>
struct SphPressureAccelerationStage {
  FluidView f;
  Kernels kernels;
  const Real* density;
  const Real* pressure;
  Vec3* a_pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    a_pressure[i] = sph_pressure_acceleration(f, kernels, density, pressure, i);
  }
};

// The pressure gradient of a kernel set, for the boundary reactions.
template <class Kernels>
struct KernelSetPressureGradient {
  Kernels kernels;
  UPF_HD Vec3 operator()(const Vec3& r) const { return kernels.pressure_gradient(r); }
};

}  // namespace upf
