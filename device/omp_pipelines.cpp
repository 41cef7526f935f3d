// The device pipeline instantiated on Thrust's OpenMP system (device_backend_omp.h).
#include "device/backend_pipelines.h"
#include "device/device_backend_omp.h"
#include "device/pipeline_factory.h"

namespace upf::device {

template <class Setup>
std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup fluid, Setup method) {
  return make_pipeline<OmpBackend>(std::move(fluid), std::move(method));
}

template std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup, PcisphSetup);
template std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup, IisphSetup);
template std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup, DfsphSetup);
template std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup, WcsphSetup);
template std::unique_ptr<DevicePipeline> make_omp_pipeline(FluidSetup, SphSetup);

}  // namespace upf::device
