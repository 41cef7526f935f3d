// The device pipeline instantiated on Thrust's OpenMP system (device_backend_omp.h).
#include "device/backend_pipelines.h"
#include "device/device_backend_omp.h"
#include "device/fluid_pipeline.h"
#include "device/iisph_method.h"
#include "device/pcisph_method.h"
#include "device/sph_method.h"
#include "device/wcsph_method.h"

namespace upf::device {

std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup fluid, PcisphSetup pcisph) {
  return std::make_unique<FluidPipeline<OmpBackend, PcisphMethod<OmpBackend>>>(std::move(fluid),
                                                                               std::move(pcisph));
}

std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup fluid, IisphSetup iisph) {
  return std::make_unique<FluidPipeline<OmpBackend, IisphMethod<OmpBackend>>>(std::move(fluid),
                                                                              std::move(iisph));
}

std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup fluid, SphSetup sph) {
  return std::make_unique<FluidPipeline<OmpBackend, SphMethod<OmpBackend>>>(std::move(fluid),
                                                                            std::move(sph));
}

std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup fluid, WcsphSetup wcsph) {
  return std::make_unique<FluidPipeline<OmpBackend, WcsphMethod<OmpBackend>>>(std::move(fluid),
                                                                              std::move(wcsph));
}

}  // namespace upf::device
