// Compiles the fluid solvers' per-particle functions with nvcc (DESIGN.md, "Executors"): the
// same source the CPU executor runs must stay device-clean until the CUDA executor launches it.
#include "solvers/fluid/fluid_forces.h"
#include "solvers/pcisph/pcisph_kernels.h"

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

}  // namespace upf::cuda
