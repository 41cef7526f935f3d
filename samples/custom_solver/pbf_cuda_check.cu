// Compiles the PBF particle stages with nvcc: the same source the CPU runs must stay device-clean
// until the device pipeline launches it (DESIGN.md, "Stages, executors and backends").
#include "pbf_stages.h"

namespace upf::pbf::cuda {

template <class Stage>
__global__ void run_stage(Stage stage, ParticleRange range) {
  const std::size_t k = std::size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k < range.size) stage(range[k]);
}

template __global__ void run_stage(PbfPredictStage, ParticleRange);
template __global__ void run_stage(ZeroScalarStage, ParticleRange);
template __global__ void run_stage(PbfLambdaStage, ParticleRange);
template __global__ void run_stage(PbfCorrectionReactionStage, ParticleRange);
template __global__ void run_stage(PbfCorrectionStage, ParticleRange);
template __global__ void run_stage(PbfApplyCorrectionStage, ParticleRange);
template __global__ void run_stage(PbfTakePredictionStage, ParticleRange);
template __global__ void run_stage(PbfVelocityTermsStage, ParticleRange);
template __global__ void run_stage(PbfVorticityStage, ParticleRange);
template __global__ void run_stage(CopyVectorStage, ParticleRange);

}  // namespace upf::pbf::cuda
