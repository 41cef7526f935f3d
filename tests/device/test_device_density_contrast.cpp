// Liquids of different rest density (solvers/fluid/density_contrast.h) on the device pipeline's
// OpenMP instantiation against the CPU executor: the number-density sums, the pressure pairs and
// PCISPH's ratio-scaled correction give the CPU path's bits. Reference: the CPU path, which
// tests/physics/test_layered_liquids.cpp checks against the layered hydrostatic pressure.
#include "tests/device/device_parity.h"

namespace upf {
namespace {

using namespace device_test;

TEST(DevicePipelineOmp, DensityContrastIsBitwiseTheCpuPath) {
  for (const char* solver : {"pcisph", "dfsph", "iisph", "wcsph"}) {
    SCOPED_TRACE(solver);
    expect_parity(testing::oil_on_water_dam_break(solver, std::string(solver) == "pcisph"), 60);
  }
}

}  // namespace
}  // namespace upf
