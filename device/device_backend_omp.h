// The device pipeline's CPU backend: Thrust's OpenMP system, compiled by the host compiler.
//
// The whole device pipeline is one source templated on a backend (DESIGN.md, "Stages, executors
// and backends"). This instantiation runs it on the CPU, with the algorithms and the memory
// discipline of the GPU (structure-of-arrays buffers, CSR lists, sorts, scans and reductions), so
// every CI run tests it bit for bit against the CPU executor without a GPU. nvcc cannot build
// Thrust's OpenMP system ("device code does not support exception handling"), so this header is
// for .cpp files only. Explicit system tags (thrust::omp) rather than THRUST_DEVICE_SYSTEM keep
// this and the CUDA instantiation distinct types in one program.
#pragma once

#include <omp.h>

#include <thrust/system/omp/execution_policy.h>
#include <thrust/system/omp/vector.h>

namespace upf::device {

struct OmpBackend {
  template <class T>
  using vector = thrust::omp::vector<T>;
  static auto policy() { return thrust::omp::par; }
  static constexpr const char* name = "omp";

  // Thrust's OpenMP loops take OpenMP's thread count; the world's count holds inside the scope
  // (a setting of the calling thread only, restored on leaving).
  class ThreadScope {
   public:
    explicit ThreadScope(int threads) : previous_(omp_get_max_threads()) {
      if (threads > 0) omp_set_num_threads(threads);
    }
    ~ThreadScope() { omp_set_num_threads(previous_); }
    ThreadScope(const ThreadScope&) = delete;
    ThreadScope& operator=(const ThreadScope&) = delete;

   private:
    int previous_;
  };
};

}  // namespace upf::device
