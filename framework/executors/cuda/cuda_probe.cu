// Compiles the shared per-particle functions for the device and offers a device query.
#include <cuda_runtime.h>

#include <string>

#include "framework/executors/cuda/cuda_probe.h"
#include "framework/kernels/cubic_spline.h"
#include "framework/kernels/muller_kernels.h"
#include "framework/neighbours/morton.h"

namespace upf::cuda {

namespace {
// Instantiates the shared functions in device code, so nvcc checks them on every build.
__global__ void compile_check(CubicSplineKernel w, const Vec3* x, Real* out, std::uint32_t n) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const MullerKernels m(w.support_radius());
  out[i] =
      w.value(x[i]) + norm(w.gradient(x[i])) + m.poly6(norm(x[i])) + Real(morton_key(i, i, i) & 1u);
}
}  // namespace

int device_count() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) return 0;
  return count;
}

std::string describe_device() {
  if (device_count() == 0) return "no CUDA device";
  cudaDeviceProp prop{};
  if (cudaGetDeviceProperties(&prop, 0) != cudaSuccess) return "CUDA device 0 not readable";
  (void)compile_check;
  return std::string(prop.name) + ", " + std::to_string(prop.totalGlobalMem >> 20) + " MiB";
}

}  // namespace upf::cuda
