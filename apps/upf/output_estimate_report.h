// What `upf run` says before its first step about the bytes its frames will take, and the
// warning when that is more than the scene's /output/size_warning.
#pragma once

#include <cstdio>

#include "framework/run/simulation_run.h"
#include "framework/scene/scene.h"

namespace upf::app {

// Prints the estimate to `out` (unless `quiet`), and a warning when it is over the threshold
// (always). The figures are uncompressed sizes: an upper bound when compression is on.
void report_output_estimate(const OutputEstimate& estimate, const SceneDescription& scene,
                            bool quiet, std::FILE* out);

}  // namespace upf::app
