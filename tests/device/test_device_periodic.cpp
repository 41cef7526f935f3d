// Periodic domains on the device pipeline (device/device_images.h): the images appended, refreshed
// after every shared stage and dropped on the device give the CPU path's bits (PeriodicDomain),
// for every fluid solver, with implicit viscosity and with surface tension.
#include "tests/device/device_parity.h"

namespace upf::device_test {
namespace {

// The dam break without end walls: each column collapses both ways and its surges cross the
// periodic faces.
TEST(DevicePipelineOmp, PeriodicDamBreakWithEveryFluidSolverIsBitwiseTheCpuPath) {
  for (const char* solver : {"pcisph", "dfsph", "iisph", "wcsph", "sph"}) {
    SCOPED_TRACE(solver);
    expect_parity(testing::periodic_dam_break(solver), 60);
  }
}

// Plane Poiseuille flow (samples/periodic_channel.json), periodic along x and z, with implicit
// viscosity: the CG's vectors are fields the images carry.
TEST(DevicePipelineOmp, PeriodicChannelWithImplicitViscosityIsBitwiseTheCpuPath) {
  auto doc = testing::load_sample_json("periodic_channel.json");
  doc["particle_spacing"] = 0.02;
  expect_parity(doc, 30);
}

// Surface tension reads its neighbours' normals, which the images carry across the faces.
TEST(DevicePipelineOmp, PeriodicSurfaceTensionIsBitwiseTheCpuPath) {
  auto doc = testing::periodic_dam_break("dfsph");
  doc["materials"]["water"]["surface_tension"] = 0.5;
  doc["materials"]["water"]["adhesion"] = {{"walls", 0.5}};
  expect_parity(doc, 40);
}

// The continuum surface force's curvatures are fitted to the images' positions too.
TEST(DevicePipelineOmp, PeriodicContinuumSurfaceForceIsBitwiseTheCpuPath) {
  auto doc = testing::periodic_dam_break("pcisph");
  doc["materials"]["water"]["surface_tension"] = 0.5;
  doc["materials"]["water"]["surface_tension_model"] = "csf";
  expect_parity(doc, 40);
}

}  // namespace
}  // namespace upf::device_test
