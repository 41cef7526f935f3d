// The device pipeline instantiated on Thrust's OpenMP system (device_backend_omp.h).
#include "device/backend_pipelines.h"
#include "device/device_backend_omp.h"
#include "device/pipeline_factory.h"

namespace upf::device {

std::unique_ptr<DevicePipeline> make_omp_pipeline(const PipelineSetup& setup) {
  return make_pipeline<OmpBackend>(setup);
}

}  // namespace upf::device
