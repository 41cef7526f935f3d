// Making a device pipeline for a prepared world (`upf run --device`, the scene key "device").
//
//   cpu   no pipeline: the CPU executor (the default, and the fastest path on a CPU)
//   omp   the device pipeline on the CPU (Thrust's OpenMP system): the GPU's algorithms and
//         memory discipline, bit for bit the CPU executor's results; for debugging device code
//         without a GPU, and what every CI run tests
//   cuda  the device pipeline on an NVIDIA GPU (sm_80, sm_90)
//
// The pipeline covers PCISPH liquids with frozen walls so far; another scene, a backend this
// build lacks, or no usable GPU is an InputError that says which.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/world/device_pipeline.h"

namespace upf {

class World;

// The names --device accepts, in this build.
std::vector<std::string> device_names();
// The pipeline `name` for `world` (prepared), or null for "cpu". `where` names the option or
// JSON path for errors.
std::unique_ptr<DevicePipeline> make_device_pipeline(std::string_view name, const World& world,
                                                     const std::string& where = "--device");

}  // namespace upf
