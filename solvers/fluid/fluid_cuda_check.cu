// Compiles the fluid solvers' particle stages with nvcc (DESIGN.md, "Stages, executors and
// backends"): every stage the CPU executor runs is instantiated here in one kernel template, so
// the same source stays device-clean until the device pipeline launches it.
#include "solvers/dem/dem_stages.h"
#include "solvers/dfsph/dfsph_kernels.h"
#include "solvers/fluid/boundary_reactions.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/iisph/iisph_kernels.h"
#include "solvers/pcisph/pcisph_kernels.h"
#include "solvers/sph/sph_kernel_sets.h"
#include "solvers/sph/sph_kernels.h"
#include "solvers/wcsph/wcsph_kernels.h"

namespace upf::cuda {

template <class Stage>
__global__ void run_stage(Stage stage, ParticleRange range) {
  const std::size_t k = std::size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k < range.size) stage(range[k]);
}

template <class Value>
__global__ void evaluate(Value value, ParticleRange range, double* out) {
  const std::size_t k = std::size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k < range.size) out[k] = double(value(range[k]));
}

template __global__ void run_stage(DensityAndGradientsStage, ParticleRange);
template __global__ void run_stage(GravityAndViscosityStage, ParticleRange);
template __global__ void run_stage(AddForceOverMassStage, ParticleRange);
template __global__ void run_stage(PredictUnownedStage, ParticleRange);
template __global__ void run_stage(SymplecticEulerStage, ParticleRange);
template __global__ void run_stage(ClearPressureStage, ParticleRange);
template __global__ void evaluate(CompressionValue, ParticleRange, double*);
template __global__ void run_stage(
    BoundaryReactionStage<PressureOverRestDensitySquared, CubicSplineGradient>, ParticleRange);
template __global__ void run_stage(
    BoundaryReactionStage<PressureOverDensitySquared, KernelSetPressureGradient<MullerKernelSet>>,
    ParticleRange);
template __global__ void run_stage(BodyWallFactorStage<PressureOverRestDensitySquared>,
                                   ParticleRange);
template __global__ void run_stage(BodyWallFloorStage, ParticleRange);
template __global__ void run_stage(BodyWallHydrostaticReactionStage, ParticleRange);

template __global__ void run_stage(PcisphPredictStage, ParticleRange);
template __global__ void run_stage(PcisphPredictedDensityStage, ParticleRange);
template __global__ void run_stage(PcisphCorrectPressureStage, ParticleRange);
template __global__ void run_stage(PcisphPressureAccelerationStage, ParticleRange);
template __global__ void run_stage(PcisphAccelerateAndPredictStage, ParticleRange);

template __global__ void run_stage(SphDensityStage<MullerKernelSet>, ParticleRange);
template __global__ void run_stage(SphViscosityStage<MullerKernelSet>, ParticleRange);
template __global__ void run_stage(SphPressureStage, ParticleRange);
template __global__ void run_stage(SphPressureAccelerationStage<MullerKernelSet>, ParticleRange);
template __global__ void run_stage(SphPressureAccelerationStage<CubicKernelSet>, ParticleRange);

template __global__ void run_stage(TaitPressureStage, ParticleRange);
template __global__ void run_stage(WcsphPressureAccelerationStage, ParticleRange);
template __global__ void run_stage(ArtificialViscosityStage, ParticleRange);

template __global__ void run_stage(InverseDiagonalStage, ParticleRange);
template __global__ void run_stage(BoundaryVelocityDivergenceStage, ParticleRange);
template __global__ void run_stage(DfsphStiffnessStage, ParticleRange);
template __global__ void run_stage(DfsphAccumulateStage, ParticleRange);
template __global__ void run_stage(DfsphWarmStartStage, ParticleRange);
template __global__ void run_stage(ClearStiffnessStage, ParticleRange);
template __global__ void run_stage(DfsphVelocityStage, ParticleRange);
template __global__ void run_stage(VelocityKickStage, ParticleRange);
template __global__ void run_stage(DfsphIntegrateStage, ParticleRange);
template __global__ void run_stage(CopyVelocityStage, ParticleRange);
template __global__ void run_stage(BoundaryReactionStage<TotalStiffness, CubicSplineGradient>,
                                   ParticleRange);

template __global__ void run_stage(IisphAdvectedDensityStage, ParticleRange);
template __global__ void run_stage(HalvePressureStage, ParticleRange);
template __global__ void run_stage(IisphPressureAccelerationStage, ParticleRange);
template __global__ void run_stage(IisphPressureUpdateStage, ParticleRange);
template __global__ void run_stage(CopyScalarStage, ParticleRange);
template __global__ void run_stage(
    BoundaryReactionStage<PressureOverDensitySquared, CubicSplineGradient>, ParticleRange);

template __global__ void run_stage(DemForcesStage, ParticleRange);
template __global__ void run_stage(DemGatherPairsStage, ParticleRange);
template __global__ void run_stage(DemBoundaryReactionStage, ParticleRange);
template __global__ void run_stage(DemKickDriftStage, ParticleRange);
template __global__ void run_stage(DemFluidStateStage, ParticleRange);
template __global__ void run_stage(DemLiquidReactionStage, ParticleRange);

}  // namespace upf::cuda
