// Determinism (DESIGN.md, "Determinism"): one scene and one build give bitwise identical results
// for any thread count, and reordering particles for locality changes no bit either, because
// neighbour lists are ordered by cell and stable id and control-flow reductions are exact.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "coupling_scenes.h"
#include "framework/core/state_stream.h"
#include "scene_helpers.h"

namespace upf {
namespace {

// Positions and velocities by stable id after `steps` steps.
testing::StateById run_steps(nlohmann::json doc, int threads, int steps) {
  testing::TestWorld tw(doc, threads);
  for (int s = 0; s < steps; ++s) tw.world->step(tw.world->next_time_step());
  return testing::state_by_id(tw.world->particles());
}

void expect_identical(const testing::StateById& a, const testing::StateById& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(testing::bitwise_differences(a, b), 0u)
      << "particles whose position or velocity differ in some bit";
}

// `first` steps on 2 threads, a checkpoint, `rest` steps on 1 thread from it: `expected`'s bits.
void expect_resumed_identical(const nlohmann::json& doc, int first, int rest,
                              const testing::StateById& expected) {
  testing::TestWorld before(doc, 2);
  for (int s = 0; s < first; ++s) before.world->step(before.world->next_time_step());
  StateWriter saved;
  before.world->save_state(saved);
  testing::TestWorld resumed(doc, 1);
  StateReader in(saved.bytes(), "after " + std::to_string(first) + " steps");
  resumed.world->restore_state(in);
  for (int s = 0; s < rest; ++s) resumed.world->step(resumed.world->next_time_step());
  expect_identical(expected, testing::state_by_id(resumed.world->particles()));
}

nlohmann::json small_dam_break(const std::string& solver = "pcisph") {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  if (solver != "pcisph") doc["materials"]["water"]["solver"] = {{"name", solver}};
  return doc;
}

TEST(Determinism, OneAndTwoThreadsGiveBitwiseIdenticalPositions) {
  const auto one = run_steps(small_dam_break(), 1, 200);
  const auto two = run_steps(small_dam_break(), 2, 200);
  expect_identical(one, two);
  // The run must actually have moved: a frozen world would pass trivially.
  const auto start = run_steps(small_dam_break(), 1, 0);
  EXPECT_GT(testing::bitwise_differences(one, start, true), 1000u);
  // A run on a busy machine changes its thread count between steps (thread_share_watch.h).
  testing::TestWorld changing(small_dam_break(), 2);
  for (int s = 0; s < 200; ++s) {
    changing.world->set_threads(1 + s % 3);
    changing.world->step(changing.world->next_time_step());
  }
  expect_identical(one, testing::state_by_id(changing.world->particles()));
}

// SPH, WCSPH, DFSPH and IISPH share PCISPH's reductions (compression_stats.h) and gather-only
// loops.
TEST(Determinism, StateEquationSolversGiveBitwiseIdenticalPositions) {
  for (const std::string solver : {"sph", "wcsph", "dfsph", "iisph"}) {
    SCOPED_TRACE(solver);
    const auto one = run_steps(small_dam_break(solver), 1, 100);
    expect_identical(one, run_steps(small_dam_break(solver), 2, 100));
    const auto start = run_steps(small_dam_break(solver), 1, 0);
    EXPECT_GT(testing::bitwise_differences(one, start, true), 1000u);
  }
}

// Two liquids of different density (density_contrast.h): the number-density sums and PCISPH's
// ratio-scaled correction, on every solver that carries them.
TEST(Determinism, DensityContrastGivesBitwiseIdenticalPositions) {
  for (const std::string solver : {"pcisph", "wcsph", "dfsph", "iisph"}) {
    SCOPED_TRACE(solver);
    const auto doc = testing::oil_on_water_dam_break(solver, solver == "pcisph");
    const auto one = run_steps(doc, 1, 80);
    expect_identical(one, run_steps(doc, 2, 80));
    EXPECT_GT(testing::bitwise_differences(one, run_steps(doc, 1, 0), true), 1000u);
  }
}

// A periodic domain (periodic_domain.h): images are ghosts refreshed after every stage and
// ordered by (cell, id) like every particle, so the bits do not depend on the thread count,
// nor on reordering, nor on a checkpoint between steps.
TEST(Determinism, PeriodicDomainGivesBitwiseIdenticalPositions) {
  const auto doc = testing::periodic_dam_break();
  const auto one = run_steps(doc, 1, 300);
  expect_identical(one, run_steps(doc, 2, 300));
  auto never_reordered = doc;
  never_reordered["neighbours"] = {{"reorder_every", 0}};
  expect_identical(one, run_steps(never_reordered, 2, 300));
  // Without a wall at x = 0 the column collapses both ways: liquid left through x = 0 and came
  // back in below x = 1.6.
  std::size_t wrapped = 0;
  const auto start = run_steps(doc, 1, 0);
  for (const auto& [id, state] : one) wrapped += state.first.x > start.at(id).first.x + Real(0.8);
  EXPECT_GT(wrapped, 10u);
  expect_resumed_identical(doc, 200, 100, one);
}

// Implicit viscosity (implicit_viscosity.h): gather-only stages and a conjugate gradient steered
// by exact dot products, so the same iteration counts and bits for any thread count; with the
// no-slip walls' extrapolated velocities (wall_velocity.h).
TEST(Determinism, ImplicitViscosityGivesBitwiseIdenticalPositions) {
  auto doc = small_dam_break();
  doc["materials"]["water"]["viscosity"] = 0.05;
  doc["materials"]["water"]["boundary_viscosity"] = 0.05;
  doc["materials"]["water"]["implicit_viscosity"] = 1;
  const auto one = run_steps(doc, 1, 100);
  expect_identical(one, run_steps(doc, 2, 100));
  EXPECT_GT(testing::bitwise_differences(one, run_steps(doc, 1, 0), true), 1000u);
  // Through a checkpoint after 60 steps: the warm start (viscosity.acceleration) goes with it.
  expect_resumed_identical(doc, 60, 40, one);
}

// DEM: each grain gathers its contacts and keeps its own contact history; pairs are computed
// from both sides with exactly opposite forces.
TEST(Determinism, GranularColumnCollapseIsBitwiseIdenticalForAnyThreadCountAndOrder) {
  auto doc = testing::load_sample_json("granular_column.json");
  const auto one = run_steps(doc, 1, 120);
  expect_identical(one, run_steps(doc, 2, 120));
  expect_identical(one, run_steps(doc, 3, 120));
  auto never = doc;
  never["neighbours"] = {{"reorder_every", 0}};
  expect_identical(one, run_steps(never, 2, 120));
  const auto start = run_steps(doc, 1, 0);
  EXPECT_GT(testing::bitwise_differences(one, start, true), 1000u);
}

// Every body's state and last fluid force and torque, as doubles: what the particle positions
// (floats) could round away.
std::vector<double> body_states_after(nlohmann::json doc, int threads, int steps) {
  testing::TestWorld tw(doc, threads);
  for (int s = 0; s < steps; ++s) tw.world->step(tw.world->next_time_step());
  const RigidBodySystem& bodies = testing::bodies_of(*tw.world);
  std::vector<double> all;
  for (std::size_t b = 0; b < bodies.bodies().size(); ++b) {
    const BodyState& s = bodies.state(b);
    for (const Eigen::Vector3d* v :
         {&s.position, &s.velocity, &s.angular_velocity, &s.fluid_force, &s.fluid_torque})
      all.insert(all.end(), v->data(), v->data() + 3);
    all.insert(all.end(), s.orientation.coeffs().data(), s.orientation.coeffs().data() + 4);
  }
  return all;
}

// With bodies: the per-body sums of the fluid's reactions and of the penetration guard's
// impulses must not depend on where the particles sit in memory. A cube shot into a block of
// water, reordered every step or never, at 1 and 2 threads: the same bits for fluid and body.
TEST(Determinism, ABodyInWaterIsBitwiseIdenticalReorderedEveryStepOrNever) {
  // The cube, turned and faster, in a shorter tank: the guard catches the water it runs over.
  nlohmann::json doc = testing::cube_shot_into_water("pcisph");
  doc["materials"]["water"]["viscosity"] = 0.002;
  doc["containers"][0]["max"] = {0.8, 0.6, 0.6};
  doc["fluid_blocks"][0]["min"] = {0.3, 0.16, 0.16};
  doc["fluid_blocks"][0]["max"] = {0.6, 0.44, 0.44};
  doc["bodies"][0]["mesh"]["position"] = {0.2, 0.3, 0.3};
  doc["bodies"][0]["mesh"]["rotation"] = {{"axis", {0, 1, 1}}, {"degrees", 20}};
  doc["bodies"][0]["velocity"] = {2.5, 0.3, 0};
  auto every = doc;
  every["neighbours"] = {{"reorder_every", 1}};
  auto never = doc;
  never["neighbours"] = {{"reorder_every", 0}};
  const auto reference = run_steps(every, 1, 300);
  expect_identical(reference, run_steps(never, 1, 300));
  expect_identical(reference, run_steps(every, 2, 300));
  expect_identical(reference, run_steps(never, 2, 300));
  const auto start = run_steps(doc, 1, 0);
  EXPECT_GT(testing::bitwise_differences(reference, start, true), 1000u);
  const std::vector<double> body = body_states_after(every, 1, 300);
  for (const auto& [variant, threads] : {std::pair{never, 1}, {every, 2}, {never, 2}}) {
    const std::vector<double> other = body_states_after(variant, threads, 300);
    ASSERT_EQ(body.size(), other.size());
    EXPECT_EQ(std::memcmp(body.data(), other.data(), body.size() * sizeof(double)), 0)
        << "body state differs at " << threads << " threads";
  }
}

TEST(Determinism, ReorderingParticlesChangesNoBit) {
  auto reordered = small_dam_break();
  reordered["neighbours"] = {{"reorder_every", 1}};
  auto never = small_dam_break();
  never["neighbours"] = {{"reorder_every", 0}};
  expect_identical(run_steps(reordered, 2, 150), run_steps(never, 2, 150));
}

}  // namespace
}  // namespace upf
