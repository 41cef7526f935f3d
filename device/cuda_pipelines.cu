// The device pipeline instantiated on Thrust's CUDA system (device_backend_cuda.cuh).
#include <cuda_runtime.h>

#include "device/backend_pipelines.h"
#include "device/device_backend_cuda.cuh"
#include "device/pcisph_pipeline.h"

namespace upf::device {

std::string cuda_unavailable_reason() {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess)
    return std::string(cudaGetErrorName(status)) + ": " + cudaGetErrorString(status);
  if (count == 0) return "no CUDA device is visible";
  return {};
}

std::unique_ptr<DevicePipeline> make_cuda_pcisph(PcisphSetup setup) {
  return std::make_unique<PcisphPipeline<CudaBackend>>(std::move(setup));
}

}  // namespace upf::device
