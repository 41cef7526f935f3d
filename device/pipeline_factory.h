// Which pressure method a setup names (fluid_setup.h), and the pipeline of a backend running it:
// the one place a new device method is listed. Each backend's translation unit
// (omp_pipelines.cpp, cuda_pipelines.cu) instantiates make_pipeline for every setup.
#pragma once

#include <memory>
#include <utility>

#include "device/dfsph_method.h"
#include "device/fluid_pipeline.h"
#include "device/iisph_method.h"
#include "device/pcisph_method.h"
#include "device/sph_method.h"
#include "device/wcsph_method.h"

namespace upf::device {

template <class Backend, class Setup>
struct MethodOf;
template <class Backend>
struct MethodOf<Backend, PcisphSetup> {
  using type = PcisphMethod<Backend>;
};
template <class Backend>
struct MethodOf<Backend, IisphSetup> {
  using type = IisphMethod<Backend>;
};
template <class Backend>
struct MethodOf<Backend, DfsphSetup> {
  using type = DfsphMethod<Backend>;
};
template <class Backend>
struct MethodOf<Backend, WcsphSetup> {
  using type = WcsphMethod<Backend>;
};
template <class Backend>
struct MethodOf<Backend, SphSetup> {
  using type = SphMethod<Backend>;
};

template <class Backend, class Setup>
std::unique_ptr<DevicePipeline> make_pipeline(FluidSetup fluid, Setup method) {
  using Method = typename MethodOf<Backend, Setup>::type;
  return std::make_unique<FluidPipeline<Backend, Method>>(std::move(fluid), std::move(method));
}

}  // namespace upf::device
