// The pipeline of a backend for a PipelineSetup: one part per solver (solver_part.h), and for a
// fluid solver the pressure method its setup names. The one place a new device method or solver
// part is listed. Each backend's translation unit (omp_pipelines.cpp, cuda_pipelines.cu) calls
// make_pipeline for its backend.
#pragma once

#include <memory>
#include <utility>
#include <variant>

#include "device/dem_part.h"
#include "device/dfsph_method.h"
#include "device/fluid_part.h"
#include "device/iisph_method.h"
#include "device/pcisph_method.h"
#include "device/pipeline_setup.h"
#include "device/solver_pipeline.h"
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

namespace factory_detail {

// The part of one solver setup (a visitor of SolverSetup).
template <class Backend>
struct MakePart {
  PipelineState<Backend>& state;

  std::unique_ptr<SolverPart<Backend>> operator()(const FluidSolverSetup& fluid) const {
    return std::visit(
        [&](const auto& method) -> std::unique_ptr<SolverPart<Backend>> {
          using Method = typename MethodOf<Backend, std::decay_t<decltype(method)>>::type;
          return std::make_unique<FluidPart<Backend, Method>>(fluid.fluid, method, state);
        },
        fluid.method);
  }
  std::unique_ptr<SolverPart<Backend>> operator()(const DemSolverSetup& dem) const {
    return std::make_unique<DemPart<Backend>>(dem, state);
  }
};

}  // namespace factory_detail

template <class Backend>
std::unique_ptr<DevicePipeline> make_pipeline(const PipelineSetup& setup) {
  auto pipeline = std::make_unique<SolverPipeline<Backend>>(setup.world);
  for (const SolverSetup& solver : setup.solvers)
    pipeline->add(std::visit(factory_detail::MakePart<Backend>{pipeline->state()}, solver));
  return pipeline;
}

}  // namespace upf::device
