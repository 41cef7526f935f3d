// The device pipeline instantiated on Thrust's CUDA system (device_backend_cuda.cuh).
#include <cuda_runtime.h>

#include <algorithm>
#include <vector>

#include "device/backend_pipelines.h"
#include "device/device_backend_cuda.cuh"
#include "device/pipeline_factory.h"

namespace upf::device {

std::string cuda_unavailable_reason() {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess)
    return std::string(cudaGetErrorName(status)) + ": " + cudaGetErrorString(status);
  if (count == 0) return "no CUDA device is visible";
  return {};
}

double cuda_copy_bandwidth_gbps(std::size_t bytes) {
  void* from = nullptr;
  void* to = nullptr;
  cudaEvent_t start = nullptr, stop = nullptr;
  bool ok = cudaMalloc(&from, bytes) == cudaSuccess && cudaMalloc(&to, bytes) == cudaSuccess &&
            cudaMemset(from, 1, bytes) == cudaSuccess && cudaEventCreate(&start) == cudaSuccess &&
            cudaEventCreate(&stop) == cudaSuccess;
  std::vector<float> ms;
  for (int k = 0; ok && k < 12; ++k) {
    ok = cudaEventRecord(start) == cudaSuccess &&
         cudaMemcpy(to, from, bytes, cudaMemcpyDeviceToDevice) == cudaSuccess &&
         cudaEventRecord(stop) == cudaSuccess && cudaEventSynchronize(stop) == cudaSuccess;
    float t = 0;
    if (ok && k >= 2 && cudaEventElapsedTime(&t, start, stop) == cudaSuccess) ms.push_back(t);
  }
  if (start) cudaEventDestroy(start);
  if (stop) cudaEventDestroy(stop);
  cudaFree(from);
  cudaFree(to);
  if (!ok || ms.empty()) return 0;
  std::sort(ms.begin(), ms.end());
  return 2.0 * double(bytes) / (double(ms[ms.size() / 2]) * 1e-3) / 1e9;
}

void cuda_memory(std::size_t& free, std::size_t& total) {
  free = total = 0;
  if (cudaMemGetInfo(&free, &total) != cudaSuccess) free = total = 0;
}

std::unique_ptr<DevicePipeline> make_cuda_pipeline(const PipelineSetup& setup) {
  return make_pipeline<CudaBackend>(setup);
}

}  // namespace upf::device
