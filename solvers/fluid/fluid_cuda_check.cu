// Compiles the fluid solvers' per-particle functions with nvcc (DESIGN.md, "Executors"): the
// same source the CPU executor runs must stay device-clean until the CUDA executor launches it.
#include "solvers/fluid/fluid_forces.h"
#include "solvers/pcisph/pcisph_kernels.h"
#include "solvers/sph/sph_kernel_sets.h"
#include "solvers/sph/sph_kernels.h"
#include "solvers/wcsph/wcsph_kernels.h"

namespace upf::cuda {

__global__ void fluid_compile_check(FluidView f, const Real* density, const Real* pressure,
                                    Vec3* gradients, Vec3* out, std::uint32_t n) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  Vec3 boundary;
  const Real rho = density_and_gradients(f, gradients, boundary, i);
  out[i] = viscosity_acceleration(f, density, gradients, i) +
           pcisph_pressure_acceleration(f, pressure, gradients, boundary, i);
  out[i].x += fluid_density(f, f.x, i) + rho;
}

template <class Kernels>
__global__ void sph_compile_check(FluidView f, Kernels w, const Real* density, const Real* pressure,
                                  Vec3* out, std::uint32_t n) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  out[i] = sph_pressure_acceleration(f, w, density, pressure, i) +
           sph_viscosity_acceleration(f, w, density, Real(1), i);
  out[i].x += sph_density(f, w, Real(1), i) + sph_pressure(density[i], Real(1000), Real(1000));
}

template __global__ void sph_compile_check<MullerKernelSet>(FluidView, MullerKernelSet, const Real*,
                                                            const Real*, Vec3*, std::uint32_t);
template __global__ void sph_compile_check<CubicKernelSet>(FluidView, CubicKernelSet, const Real*,
                                                           const Real*, Vec3*, std::uint32_t);

__global__ void wcsph_compile_check(FluidView f, const Real* density, const Real* pressure,
                                    const Vec3* gradients, Vec3* out, std::uint32_t n) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  out[i] = wcsph_pressure_acceleration(f, density, pressure, gradients, out[i], i) +
           artificial_viscosity_acceleration(f, density, gradients, Real(1), i);
  out[i].x += tait_pressure(density[i], Real(1000), Real(1e5));
}

}  // namespace upf::cuda
