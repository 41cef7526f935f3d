// Making a device pipeline for a prepared world (`upf run --device`, the scene key "device").
//
//   cpu   no pipeline: the CPU executor (the default, and the fastest path on a CPU)
//   omp   the device pipeline on the CPU (Thrust's OpenMP system): the GPU's algorithms and
//         memory discipline, bit for bit the CPU executor's results; for debugging device code
//         without a GPU, and what every CI run tests
//   cuda  the device pipeline on an NVIDIA GPU (sm_80, sm_90)
//
// The pipeline runs the PCISPH, IISPH, DFSPH, WCSPH, SPH and DEM solvers, in any mix, with frozen
// walls and bodies; a scene with another solver (a plug-in's), a backend this build lacks, or no
// usable GPU is an InputError that says which.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/world/device_pipeline.h"

namespace upf {

class World;

// Device memory the pipeline needs for a prepared world: checked against the GPU's free memory
// before a CUDA run starts.
std::size_t estimated_device_bytes(const World& world);

// Copy bandwidth of `device`'s memory (bytes read plus written per second, in GB/s) over a buffer
// of `bytes`: cudaMemcpy device to device for "cuda", memcpy in host memory otherwise. The
// ceiling that the benchmark's traffic figures are fractions of.
double copy_bandwidth_gbps(std::string_view device, std::size_t bytes);

// The names --device accepts, in this build.
std::vector<std::string> device_names();
// What make_device_pipeline checks of the name and the scene, without touching a GPU: for
// `upf validate`. Throws InputError.
void check_device(std::string_view name, const World& world, const std::string& where);
// The pipeline `name` for `world` (prepared), or null for "cpu". `where` names the option or
// JSON path for errors.
std::unique_ptr<DevicePipeline> make_device_pipeline(std::string_view name, const World& world,
                                                     const std::string& where = "--device");

}  // namespace upf
