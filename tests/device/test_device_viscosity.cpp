// Implicit viscosity (solvers/fluid/implicit_viscosity.h) and the no-slip walls of the viscous sums
// (wall_velocity.h) on the device pipeline's OpenMP instantiation against the CPU executor: the
// conjugate gradient's stages, its exact dot products (so its iteration counts), its warm start
// (the field viscosity.acceleration) and the viscous reactions on a body give the CPU path's bits.
// Reference: the CPU path, which tests/physics/test_implicit_viscosity.cpp checks against Stokes.
#include "tests/device/device_parity.h"

namespace upf {
namespace {

using namespace device_test;

nlohmann::json viscous_cube_shot_into_water(const std::string& solver, bool implicit) {
  auto doc = testing::cube_shot_into_water({{"name", solver}});
  doc["particle_spacing"] = 0.04;
  doc["bodies"][0]["velocity"] = {2.0, 0, 0};
  auto& water = doc["materials"]["water"];
  water["viscosity"] = 0.05;
  water["boundary_viscosity"] = 0.05;
  water["implicit_viscosity"] = implicit ? 1 : 0;
  return doc;
}

TEST(DevicePipelineOmp, ImplicitViscosityIsBitwiseTheCpuPath) {
  for (const char* solver : {"pcisph", "iisph"}) {
    SCOPED_TRACE(solver);
    expect_parity(viscous_cube_shot_into_water(solver, true), 60);
  }
}

TEST(DevicePipelineOmp, NoSlipWallsOfTheExplicitViscosityAreBitwiseTheCpuPath) {
  expect_parity(viscous_cube_shot_into_water("dfsph", false), 60);
}

// Free-slip walls and body (framework/boundary/slip_normal.h): the body's normals turn with it in
// the placement stage, and the walls' velocities take them.
TEST(DevicePipelineOmp, FreeSlipWallsAndBodiesAreBitwiseTheCpuPath) {
  auto doc = viscous_cube_shot_into_water("pcisph", false);
  doc["materials"]["walls"]["free_slip"] = 1;
  doc["materials"]["solid"]["free_slip"] = 1;
  expect_parity(doc, 60);
}

}  // namespace
}  // namespace upf
