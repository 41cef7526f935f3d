// The pipeline of each backend, made by its own translation unit (omp_pipelines.cpp, built by
// the host compiler; cuda_pipelines.cu, by nvcc), for device_pipelines.cpp. Internal.
#pragma once

#include <memory>
#include <string>

#include "device/pcisph_setup.h"
#include "framework/world/device_pipeline.h"

namespace upf::device {

std::unique_ptr<DevicePipeline> make_omp_pcisph(PcisphSetup setup);
// Empty when a CUDA device can be used, else why not (the CUDA runtime's error name and text).
std::string cuda_unavailable_reason();
std::unique_ptr<DevicePipeline> make_cuda_pcisph(PcisphSetup setup);

}  // namespace upf::device
