// Compiles the PBF per-particle functions with nvcc: the same source the CPU runs must stay
// device-clean until the CUDA executor launches it (DESIGN.md, "Executors").
#include "pbf_kernels.h"

namespace upf::pbf::cuda {

__global__ void pbf_compile_check(FluidView f, const Vec3* xs, Real* lambda, PbfPairTerms terms,
                                  const Vec3* omega, PbfConstants c, Vec3* out, std::uint32_t n) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  lambda[i] = pbf_lambda(f, xs, c, terms, i);
  const PbfVelocityTerms t = pbf_velocity_terms(f, Real(0.01), i);
  out[i] = pbf_position_correction(f, lambda, terms, i) + t.xsph + t.omega +
           pbf_vorticity_acceleration(f, omega, Real(0.1), i);
}

}  // namespace upf::pbf::cuda
