// The device pipeline on Thrust's OpenMP system ("--device omp") against the CPU executor: the
// same scene stepped both ways (PCISPH, IISPH, DFSPH, WCSPH, SPH, DEM linear and Hertz; walls,
// dynamic and kinematic bodies; grains in water) gives bitwise identical particles (positions,
// velocities, density, pressure, every field), bodies (pose, velocity, fluid force and torque),
// step statistics and checkpoints, for 1 and 2 threads (DESIGN.md, "Determinism": the device
// pipeline's CPU instantiation is bitwise the CPU path). Reference: the CPU path, whose physics
// tests/physics checks against analytic and experimental references.
#include "tests/device/device_parity.h"

namespace upf {
namespace {

using namespace device_test;

TEST(DevicePipelineOmp, DamBreakIsBitwiseTheCpuPath) {
  expect_parity(small_dam_break(), 120);
}

TEST(DevicePipelineOmp, HydrostaticTankIsBitwiseTheCpuPath) {
  expect_parity(small_tank(), 80);
}

// The wall pressure (solvers/fluid/boundary_pressure.h) of every solver that offers it.
TEST(DevicePipelineOmp, WallPressureIsBitwiseTheCpuPath) {
  for (const char* solver : {"pcisph", "iisph", "dfsph", "wcsph"}) {
    SCOPED_TRACE(solver);
    auto doc = small_tank();
    doc["materials"]["water"]["solver"] = {{"name", solver}, {"wall_pressure", 1}};
    expect_parity(doc, 40);
  }
}

TEST(DevicePipelineOmp, WcsphDamBreakIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["solver"] = {{"name", "wcsph"}};
  expect_parity(doc, 150);
  doc["materials"]["water"]["solver"] = {{"name", "wcsph"}, {"alpha", 0}};
  expect_parity(doc, 60);
}

TEST(DevicePipelineOmp, SphWithEitherKernelSetIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["solver"] = {{"name", "sph"}};
  expect_parity(doc, 120);
  // The paper's kernels (poly6, spiky, viscosity) with the viscosity they need to stay stable.
  doc["materials"]["water"]["solver"] = {{"name", "sph"}, {"cubic_spline", 0}, {"viscosity", 20}};
  expect_parity(doc, 60);
}

TEST(DevicePipelineOmp, IisphDamBreakIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["solver"] = {{"name", "iisph"}};
  expect_parity(doc, 120);
  doc["materials"]["water"]["solver"] = {{"name", "iisph"}, {"stop_percentile", 95}};
  expect_parity(doc, 40);
  // Checked against densities summed at the predicted positions (iisph_solve.h).
  doc["materials"]["water"]["solver"] = {
      {"name", "iisph"}, {"stop_percentile", 100}, {"summed_density_check", 1}};
  expect_parity(doc, 60);
}

// Four bodies of densities 300 to 1500 dropped into a pool (samples/floating_objects.json, at
// twice the spacing): placement, reactions, per-body sums and Bullet, from the fall to the splash.
TEST(DevicePipelineOmp, FloatingObjectsAreBitwiseTheCpuPath) {
  auto doc = testing::load_sample_json("floating_objects.json");
  doc["particle_spacing"] = 0.04;
  for (auto& body : doc["bodies"]) {
    const std::string file = body["mesh"]["file"];
    body["mesh"]["file"] = testing::kTestMeshes + file.substr(file.rfind('/') + 1);
  }
  expect_parity(doc, 150);
}

// A cube shot at 0.5 m/s into a block of water, with each fluid solver: the slam pushes fluid
// particles into the cube, and the penetration guard's moves and impulses match too.
TEST(DevicePipelineOmp, BodySlamWithEveryFluidSolverIsBitwiseTheCpuPath) {
  std::size_t guarded = 0;
  for (const char* solver : {"pcisph", "iisph", "dfsph", "wcsph", "sph"}) {
    SCOPED_TRACE(solver);
    nlohmann::json params = {{"name", solver}};
    // No liquid column under gravity to derive a sound speed from: ten times the slam's speed.
    if (std::string(solver) == "wcsph") params["sound_speed"] = 20;
    if (std::string(solver) == "sph") params["stiffness"] = 800;  // 2 c^2, c = 20 m/s
    auto doc = testing::cube_shot_into_water(params);
    doc["particle_spacing"] = 0.04;
    doc["bodies"][0]["velocity"] = {2.0, 0, 0};
    guarded += expect_parity(doc, 120);
  }
  EXPECT_GT(guarded, 0u) << "the guard never acted: the test would not see it differ";
}

// Surface tension and adhesion (solvers/fluid/surface_forces.h): the normals' pass, the forces,
// and the adhesion's reactions on the cube, with two fluid solvers.
TEST(DevicePipelineOmp, SurfaceTensionAndAdhesionAreBitwiseTheCpuPath) {
  for (const char* solver : {"pcisph", "dfsph"}) {
    SCOPED_TRACE(solver);
    auto doc = testing::cube_shot_into_water({{"name", solver}});
    doc["particle_spacing"] = 0.04;
    doc["bodies"][0]["velocity"] = {2.0, 0, 0};
    doc["materials"]["water"]["surface_tension"] = 0.5;
    doc["materials"]["water"]["adhesion"] = {{"solid", 2.0}, {"walls", 0.5}};
    expect_parity(doc, 120);
  }
}

// The continuum surface force (continuum_surface_force.h): its curvature pass between the normals
// and the forces, and its neighbours' curvatures in the forces.
TEST(DevicePipelineOmp, ContinuumSurfaceForceIsBitwiseTheCpuPath) {
  auto doc = testing::cube_shot_into_water({{"name", "pcisph"}});
  doc["particle_spacing"] = 0.04;
  doc["bodies"][0]["velocity"] = {2.0, 0, 0};
  doc["materials"]["water"]["surface_tension"] = 0.5;
  doc["materials"]["water"]["surface_tension_model"] = "csf";
  expect_parity(doc, 120);
}

// A frozen paddle turning in the dam break: a kinematic body's particles placed on the device.
TEST(DevicePipelineOmp, KinematicPaddleIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["steel"] = {{"type", "frozen"}};
  doc["bodies"] = {{{"name", "paddle"},
                    {"material", "steel"},
                    {"mesh",
                     {{"file", testing::kTestMeshes + "unit_box.obj"},
                      {"scale", {0.3, 0.08, 0.3}},
                      {"position", {1.2, 0.3, 0.2}}}},
                    {"motion", {{"angular_velocity", {0, 0, 3.0}}}}}};
  expect_parity(doc, 80);
}

// A fixed block and the paddle with the wall pressure: reactions on frozen body particles (their
// P_b and hydrostatic parts, boundary_reactions.h) and the bodies' fluid forces summed on the
// device.
TEST(DevicePipelineOmp, FixedAndTurningObstaclesAreBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  testing::add_fixed_block_and_paddle(doc);
  expect_parity(doc, 130);
  // The parity is not that of two zero forces: the surge has reached both bodies (the block at
  // step 60, the paddle at about 110).
  Stepped cpu = start(doc, 2, "cpu");
  step(cpu, 130);
  for (const NamedBodyState& b : cpu.tw.world->body_systems().front()->body_states()) {
    SCOPED_TRACE(b.name);
    EXPECT_GT(b.state.fluid_force.norm(), 1.0);  // N
  }
}

TEST(DevicePipelineOmp, DfsphDamBreakIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["solver"] = {{"name", "dfsph"}};
  expect_parity(doc, 120);
  // Without the divergence-free solve and warm starts, and with a percentile stopping test.
  doc["materials"]["water"]["solver"] = {
      {"name", "dfsph"}, {"divergence", 0}, {"warm_start", 0}, {"stop_percentile", 95}};
  expect_parity(doc, 40);
  // Checked against densities summed at the predicted positions (dfsph_summed_density.h).
  doc["materials"]["water"]["solver"] = {
      {"name", "dfsph"}, {"stop_percentile", 100}, {"summed_density_check", 1}};
  expect_parity(doc, 60);
}

TEST(DevicePipelineOmp, PercentileStoppingTestIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["solver"]["stop_percentile"] = 99;
  expect_parity(doc, 40);
}

// Emitters and sinks (issue 40) change the count before steps: the device pipeline takes the
// particles again (World::apply_sources) and gives the CPU path's bits; so does a checkpoint.
void expect_sources_bitwise(const nlohmann::json& doc, int steps) {
  Stepped cpu = start(doc, 2, "cpu");
  Stepped omp = start(doc, 2, "omp");
  ASSERT_NE(omp.tw.world->device(), nullptr);
  std::size_t added = 0, removed = 0;
  for (int k = 0; k < steps; ++k) {
    step(cpu, 1);
    step(omp, 1);
    added += cpu.tw.world->last_step().sources.added;
    removed += cpu.tw.world->last_step().sources.removed;
    ASSERT_EQ(omp.tw.world->last_step().sources.added, cpu.tw.world->last_step().sources.added);
    ASSERT_EQ(omp.tw.world->last_step().sources.removed, cpu.tw.world->last_step().sources.removed);
  }
  EXPECT_GT(added, 300u);
  EXPECT_GT(removed, 20u);
  EXPECT_EQ(cpu.dts, omp.dts);
  EXPECT_EQ(cpu.iterations, omp.iterations);
  expect_identical(cpu.tw.world->particles(), omp.tw.world->particles());
  StateWriter a, b;
  cpu.tw.world->save_state(a);
  omp.tw.world->save_state(b);
  EXPECT_TRUE(a.bytes() == b.bytes()) << "checkpoints differ";
}

TEST(DevicePipelineOmp, APourIntoADrainIsBitwiseTheCpuPath) {
  expect_sources_bitwise(testing::hose_into_a_drain(), 90);
}

// An inlet with a velocity profile and an outlet with an outflow buffer: the velocities they set
// before each step reach the device as any host edit does.
TEST(DevicePipelineOmp, AChannelWithOpenEndsIsBitwiseTheCpuPath) {
  expect_sources_bitwise(testing::channel_with_open_ends(), 120);
}

// Host edits between steps (what Python and the run loop's resume do) reach the device, and the
// device's state reaches checkpoints.
TEST(DevicePipelineOmp, HostEditsAndCheckpointsSeeTheCurrentState) {
  Stepped cpu = start(small_dam_break(), 2, "cpu");
  Stepped omp = start(small_dam_break(), 2, "omp");
  step(cpu, 20);
  step(omp, 20);
  for (Stepped* s : {&cpu, &omp}) {
    Particles& p = s->tw.world->particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Liquid) p.velocity[i].x += Real(0.5);
  }
  step(cpu, 20);
  step(omp, 20);
  expect_identical(cpu.tw.world->particles(), omp.tw.world->particles());
  StateWriter a, b;
  cpu.tw.world->save_state(a);
  omp.tw.world->save_state(b);
  EXPECT_TRUE(a.bytes() == b.bytes()) << "checkpoints differ";
}

TEST(DevicePipelineOmp, UnstableRunNamesTheParticleAndKeepsTheLastGoodState) {
  auto doc = small_dam_break();
  doc["stability"]["max_speed"] = 1.0;  // the collapse passes 1 m/s within the first 0.2 s
  for (const std::string device : {"cpu", "omp"}) {
    SCOPED_TRACE(device);
    Stepped s = start(doc, 2, device);
    try {
      step(s, 400);
      FAIL() << "no instability";
    } catch (const InstabilityError& e) {
      EXPECT_NE(std::string(e.what()).find("speed"), std::string::npos) << e.what();
      EXPECT_EQ(s.tw.world->last_good().size(), s.tw.world->particles().size());
    }
  }
}

// The sand pile's collapse (samples/sand_pile.json): grain-grain and grain-wall contacts with
// their springs carried from step to step, linear and Hertz.
TEST(DevicePipelineOmp, SandPileIsBitwiseTheCpuPath) {
  auto doc = testing::load_sample_json("sand_pile.json");
  expect_parity(doc, 60);
  doc["materials"]["sand"]["solver"] = "dem_hertz";
  doc["materials"]["sand"]["youngs_modulus"] = 5e6;
  doc["materials"]["sand"]["poisson_ratio"] = 0.3;
  expect_parity(doc, 25);
}

// Sand poured onto a floating box and into the pool around it (samples/sand_into_water.json,
// coarser): DEM, PCISPH and Bullet in one step; grain-body contacts push the box through
// boundary_force, drag and buoyancy push the water through liquid_force.
TEST(DevicePipelineOmp, SandIntoWaterWithABodyIsBitwiseTheCpuPath) {
  auto doc = testing::load_sample_json("sand_into_water.json");
  doc["particle_spacing"] = 0.03;
  doc["granular_blocks"] = {
      {{"material", "sand"}, {"min", {0.14, 0.42, 0.14}}, {"max", {0.26, 0.5, 0.26}}},
      {{"material", "sand"}, {"min", {0.45, 0.32, 0.15}}, {"max", {0.55, 0.38, 0.25}}}};
  for (auto& body : doc["bodies"]) {
    const std::string file = body["mesh"]["file"];
    body["mesh"]["file"] = testing::kTestMeshes + file.substr(file.rfind('/') + 1);
  }
  expect_parity(doc, 100);
  // Both couplings acted: grains went under the surface (y = 0.3 m) and some rest on the box.
  Stepped cpu = start(doc, 2, "cpu");
  step(cpu, 100);
  const Particles& p = cpu.tw.world->particles();
  std::size_t wet = 0, on_box = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Granular) continue;
    wet += p.position[i].y < Real(0.28);
    on_box +=
        p.position[i].x > Real(0.14) && p.position[i].x < Real(0.26) && p.position[i].y > Real(0.3);
  }
  EXPECT_GT(wet, 50u);
  EXPECT_GT(on_box, 50u);
}

// Checkpoints carry DEM's springs: the device's reach the host solver when the state is saved,
// and a restored world's go back up, so a resumed run continues bit for bit.
TEST(DevicePipelineOmp, CheckpointsCarryTheDeviceSprings) {
  const auto doc = testing::load_sample_json("sand_pile.json");
  Stepped cpu = start(doc, 2, "cpu");
  Stepped omp = start(doc, 2, "omp");
  step(cpu, 30);
  step(omp, 30);
  StateWriter a, b;
  cpu.tw.world->save_state(a);
  omp.tw.world->save_state(b);
  ASSERT_TRUE(a.bytes() == b.bytes()) << "checkpoints differ";
  // A fresh device world resumed from the checkpoint.
  Stepped resumed = start(doc, 2, "omp");
  StateReader in(a.bytes(), "checkpoint");
  resumed.tw.world->restore_state(in);
  step(cpu, 30);
  step(resumed, 30);
  expect_identical(cpu.tw.world->particles(), resumed.tw.world->particles());
}

// A solver the pipeline has no part for.
class IdleSolver : public Solver {
 public:
  std::string_view name() const override { return "idle"; }
  void prepare(World&) override {}
  Real max_time_step(const World&) const override { return Real(1); }
  std::vector<std::string> stages() const override { return {}; }
  void step(World&, Real, StageRunner&) override {}
  SolverStats stats() const override { return {}; }
};

TEST(DevicePipeline, ScenesItDoesNotCoverAreRefusedWithTheReason) {
  {
    testing::TestWorld tw(small_dam_break(), 1);
    tw.world->add_solver(std::make_unique<IdleSolver>());
    try {
      make_device_pipeline("omp", *tw.world);
      FAIL() << "a solver without a device part accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'idle'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("--device cpu"), std::string::npos) << e.what();
    }
  }
  testing::TestWorld tw(small_dam_break(), 1);
  try {
    make_device_pipeline("gpu0", *tw.world, "/device");
    FAIL() << "unknown device accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("allowed: cpu, omp"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("/device"), std::string::npos) << e.what();
  }
  EXPECT_EQ(make_device_pipeline("cpu", *tw.world), nullptr);
}

}  // namespace
}  // namespace upf
