// The device pipeline on Thrust's OpenMP system ("--device omp") against the CPU executor: the
// same scene stepped both ways (PCISPH, IISPH, WCSPH, SPH) gives bitwise identical particles
// (positions, velocities, density, pressure, every field), step statistics and checkpoints, for 1
// and 2 threads (DESIGN.md, "Determinism": the device pipeline's CPU instantiation is bitwise the
// CPU path). Reference: the CPU path, whose physics tests/physics checks against analytic and
// experimental references.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "../physics/coupling_scenes.h"
#include "../physics/scene_helpers.h"
#include "device/device_pipelines.h"
#include "framework/core/errors.h"
#include "framework/core/state_stream.h"

namespace upf {
namespace {

nlohmann::json small_dam_break() {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  return doc;
}

nlohmann::json small_tank() {
  auto doc = testing::load_sample_json("hydrostatic_tank.json");
  doc["particle_spacing"] = 0.04;
  return doc;
}

template <class T>
std::size_t bitwise_differences(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
  return n;
}

// Every array and every field of two worlds' particles, in memory order (both reorder on the
// same cadence, so the orders agree too).
void expect_identical(const Particles& a, const Particles& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(bitwise_differences(a.position, b.position), 0u) << "positions differ";
  EXPECT_EQ(bitwise_differences(a.velocity, b.velocity), 0u) << "velocities differ";
  ASSERT_EQ(a.scalar_fields().size(), b.scalar_fields().size());
  for (const auto& [name, f] : a.scalar_fields())
    EXPECT_EQ(bitwise_differences(f.values, b.scalar_fields().at(name).values), 0u) << name;
  for (const auto& [name, f] : a.vector_fields())
    EXPECT_EQ(bitwise_differences(f.values, b.vector_fields().at(name).values), 0u) << name;
}

struct Stepped {
  testing::TestWorld tw;
  std::vector<int> iterations;
  std::vector<double> dts;
};

// `steps` steps towards the scene's frames (World::step_towards), as `upf run` takes them.
void step(Stepped& s, int steps) {
  World& w = *s.tw.world;
  const double frame = 1.0 / 30.0;
  for (int k = 0; k < steps; ++k) {
    const double stop = (std::floor(w.time() / frame + 1e-9) + 1) * frame;
    w.step_towards(stop);
    s.iterations.push_back(w.last_step().solver.iterations);
    s.dts.push_back(w.last_step().dt);
  }
}

Stepped start(const nlohmann::json& doc, int threads, const std::string& device) {
  Stepped s{testing::TestWorld(doc, threads), {}, {}};
  s.tw.world->set_device(make_device_pipeline(device, *s.tw.world));
  return s;
}

void expect_parity(const nlohmann::json& doc, int steps) {
  for (int threads : {1, 2}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    Stepped cpu = start(doc, threads, "cpu");
    Stepped omp = start(doc, threads, "omp");
    ASSERT_NE(omp.tw.world->device(), nullptr);
    EXPECT_EQ(omp.tw.world->device()->name(), "omp");
    const auto initial = testing::state_by_id(cpu.tw.world->particles());
    step(cpu, steps);
    step(omp, steps);
    expect_identical(cpu.tw.world->particles(), omp.tw.world->particles());
    EXPECT_EQ(cpu.iterations, omp.iterations);
    EXPECT_EQ(cpu.dts, omp.dts);
    EXPECT_EQ(cpu.tw.world->time(), omp.tw.world->time());
    // The run must have moved: a frozen world would pass trivially.
    EXPECT_GT(testing::bitwise_differences(testing::state_by_id(cpu.tw.world->particles()), initial,
                                           true),
              cpu.tw.world->particles().count(ParticleType::Liquid) / 2);
  }
}

TEST(DevicePipelineOmp, DamBreakIsBitwiseTheCpuPath) {
  expect_parity(small_dam_break(), 120);
}

TEST(DevicePipelineOmp, HydrostaticTankIsBitwiseTheCpuPath) {
  expect_parity(small_tank(), 80);
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
}

TEST(DevicePipelineOmp, PercentileStoppingTestIsBitwiseTheCpuPath) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["solver"]["stop_percentile"] = 99;
  expect_parity(doc, 40);
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

TEST(DevicePipeline, ScenesItDoesNotCoverAreRefusedWithTheReason) {
  {
    testing::TestWorld tw(
        testing::tank_with_body("pcisph", 700, "unit_box.obj", 0.1, {0.25, 0.3, 0.25}), 1);
    try {
      make_device_pipeline("omp", *tw.world);
      FAIL() << "bodies accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("rigid bodies"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("--device cpu"), std::string::npos) << e.what();
    }
  }
  {
    auto doc = small_dam_break();
    doc["materials"]["water"]["solver"] = {{"name", "dfsph"}};
    testing::TestWorld tw(doc, 1);
    EXPECT_THROW(make_device_pipeline("omp", *tw.world), InputError);
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
