// The device pipeline instantiated on Thrust's OpenMP system (device_backend_omp.h).
#include "device/backend_pipelines.h"
#include "device/device_backend_omp.h"
#include "device/pcisph_pipeline.h"

namespace upf::device {

std::unique_ptr<DevicePipeline> make_omp_pcisph(PcisphSetup setup) {
  return std::make_unique<PcisphPipeline<OmpBackend>>(std::move(setup));
}

}  // namespace upf::device
