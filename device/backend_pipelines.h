// The pipeline of each backend, made by its own translation unit (omp_pipelines.cpp, built by
// the host compiler; cuda_pipelines.cu, by nvcc), for device_pipelines.cpp. Internal.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "device/pipeline_setup.h"
#include "framework/world/device_pipeline.h"

namespace upf::device {

std::unique_ptr<DevicePipeline> make_omp_pipeline(const PipelineSetup& setup);
// Empty when a CUDA device can be used, else why not (the CUDA runtime's error name and text).
std::string cuda_unavailable_reason();
std::unique_ptr<DevicePipeline> make_cuda_pipeline(const PipelineSetup& setup);
// Device-to-device copy bandwidth over a buffer of `bytes`, counting bytes read plus written, in
// GB/s: the median of 10 copies after 2 warm-ups, timed with CUDA events. 0 if it failed.
double cuda_copy_bandwidth_gbps(std::size_t bytes);
// Free and total memory of the current CUDA device, in bytes.
void cuda_memory(std::size_t& free, std::size_t& total);

}  // namespace upf::device
