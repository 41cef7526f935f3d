// The device pipeline's GPU backend: Thrust's CUDA system (CUB sorts, scans and reductions),
// compiled by nvcc for sm_80 and sm_90. The same pipeline source as device_backend_omp.h's.
#pragma once

#include <thrust/system/cuda/execution_policy.h>
#include <thrust/system/cuda/vector.h>

namespace upf::device {

struct CudaBackend {
  template <class T>
  using vector = thrust::cuda::vector<T>;
  static auto policy() { return thrust::cuda::par; }
  static constexpr const char* name = "cuda";

  // The GPU's parallelism is not the world's thread count.
  struct ThreadScope {
    explicit ThreadScope(int) {}
  };
};

}  // namespace upf::device
