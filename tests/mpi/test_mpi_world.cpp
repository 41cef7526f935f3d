// A world split over MPI ranks gives the one-rank results to the bit (DESIGN.md, "Determinism";
// issue 23). Run by ctest as `mpirun -n P upf_mpi_tests` for P = 1, 2, 3 and 4: every rank steps
// its share of the scene, rank 0 gathers the particles by id and steps the same scene alone, and
// every particle's position, velocity and named fields must match in every bit. The reference is
// the single-rank run itself: the decomposition must change nothing.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "../physics/coupling_scenes.h"
#include "../physics/pour_scenes.h"
#include "../physics/scene_helpers.h"
#include "coupling/bodies/rigid_body_system.h"
#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/mpi/mpi_domain.h"

namespace upf {
namespace {

int rank_here() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int ranks_here() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// Every array of every particle in id order, as bytes: positions, velocities and every field.
struct Snapshot {
  std::vector<std::uint32_t> ids;
  std::vector<std::uint8_t> bytes;
  std::size_t per_particle = 0;
};

Snapshot snapshot_of(const Particles& p) {
  Snapshot s;
  s.ids = p.id;
  s.per_particle = p.packed_size();
  std::vector<std::uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });
  p.pack(order.data(), order.size(), s.bytes);
  std::sort(s.ids.begin(), s.ids.end());
  return s;
}

// Body states as doubles (position, velocity, spin, fluid force and torque, orientation).
std::vector<double> body_numbers(const World& world) {
  std::vector<double> all;
  for (const auto& system : world.body_systems())
    for (const NamedBodyState& b : system->body_states()) {
      const BodyState& s = b.state;
      for (const Eigen::Vector3d* v :
           {&s.position, &s.velocity, &s.angular_velocity, &s.fluid_force, &s.fluid_torque})
        all.insert(all.end(), v->data(), v->data() + 3);
      all.insert(all.end(), s.orientation.coeffs().data(), s.orientation.coeffs().data() + 4);
    }
  return all;
}

struct Outcome {
  Snapshot particles;
  std::vector<double> bodies;
  std::uint64_t ghosts = 0;            // summed over ranks, at the last exchange
  std::size_t added = 0, removed = 0;  // by emitters and sinks, as the steps reported them
};

// Writes a checkpoint (on a split world: the gathered world, on every rank) and continues from
// its bytes, as a run with checkpoints does (simulation_run.cpp).
void checkpoint_and_resume(World& world) {
  StateWriter out;
  world.save_state(out);
  std::vector<char> bytes = out.bytes();
  if (world.domain()) world.domain()->broadcast(bytes);
  StateReader in(std::move(bytes), "checkpoint");
  world.restore_state(in);
}

// `steps` steps of `doc`, split over every rank when `split`, else on this rank alone; through a
// checkpoint after step `checkpoint_at` when it is positive.
Outcome run(const nlohmann::json& doc, int steps, bool split, int rebalance_every = 10,
            int checkpoint_at = 0) {
  testing::TestWorld tw(doc, 1);
  World& world = *tw.world;
  if (split)
    world.set_domain(std::make_unique<MpiDomain>(MPI_COMM_WORLD, world.settings().support_radius(),
                                                 rebalance_every, world.settings().periodic));
  std::uint64_t ghosts = 0;
  std::size_t added = 0, removed = 0;
  for (int s = 0; s < steps; ++s) {
    if (s == checkpoint_at && s > 0) checkpoint_and_resume(world);
    world.step(world.next_time_step());
    if (split) ghosts = world.domain()->traffic().ghosts;
    added += world.last_step().sources.added;
    removed += world.last_step().sources.removed;
  }
  Outcome out;
  out.added = added;
  out.removed = removed;
  out.bodies = body_numbers(world);
  if (!split) {
    out.particles = snapshot_of(world.particles());
    return out;
  }
  out.ghosts = std::uint64_t(world.domain()->sum(std::int64_t(ghosts)));
  Particles whole;
  world.domain()->gather(world.particles(), whole);
  if (rank_here() == 0) out.particles = snapshot_of(whole);
  return out;
}

// On rank 0: the split run against the one-rank run, every byte of every particle.
// The split run's outcome goes to `split_out` when given.
void expect_same_as_one_rank(const nlohmann::json& doc, int steps, int rebalance_every = 10,
                             int checkpoint_at = 0, Outcome* split_out = nullptr) {
  const Outcome split = run(doc, steps, true, rebalance_every, checkpoint_at);
  if (split_out) *split_out = split;
  if (rank_here() != 0) return;
  const Outcome alone = run(doc, steps, false);
  ASSERT_EQ(split.particles.ids, alone.particles.ids) << "the gathered particles' ids";
  EXPECT_EQ(split.added, alone.added) << "particles emitted, as the split steps reported them";
  EXPECT_EQ(split.removed, alone.removed) << "particles removed, summed over the ranks";
  ASSERT_EQ(split.particles.per_particle, alone.particles.per_particle);
  const auto& a = split.particles.bytes;
  const auto& b = alone.particles.bytes;
  ASSERT_EQ(a.size(), b.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < a.size(); ++k) differing += a[k] != b[k];
  EXPECT_EQ(differing, 0u) << "bytes of the gathered particles that differ from one rank, out of "
                           << a.size() << " (" << alone.particles.ids.size() << " particles)";
  ASSERT_EQ(split.bodies.size(), alone.bodies.size());
  EXPECT_EQ(
      std::memcmp(split.bodies.data(), alone.bodies.data(), split.bodies.size() * sizeof(double)),
      0)
      << "body states differ";
  if (ranks_here() > 1) {
    EXPECT_GT(split.ghosts, 0u) << "a split world with no ghosts split nothing";
  }
  // And the scene moved: a world at rest would pass trivially.
  const Outcome start = run(doc, 0, false);
  EXPECT_NE(std::memcmp(start.particles.bytes.data(), alone.particles.bytes.data(),
                        std::min(start.particles.bytes.size(), alone.particles.bytes.size())),
            0);
}

nlohmann::json small_dam_break(const std::string& solver = "pcisph") {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  if (solver != "pcisph") doc["materials"]["water"]["solver"] = {{"name", solver}};
  return doc;
}

TEST(SplitWorld, PcisphDamBreakIsBitwiseTheOneRankRun) {
  expect_same_as_one_rank(small_dam_break(), 150);
}

TEST(SplitWorld, EveryFluidSolverIsBitwiseTheOneRankRun) {
  for (const std::string solver : {"sph", "wcsph", "iisph", "dfsph"}) {
    SCOPED_TRACE(solver);
    expect_same_as_one_rank(small_dam_break(solver), 60);
  }
}

// Surface tension reads its neighbours' normals, so ghosts must carry them (a field refreshed after
// each particle stage); adhesion to the walls, the tension with two solvers.
TEST(SplitWorld, SurfaceTensionIsBitwiseTheOneRankRun) {
  for (const std::string solver : {"pcisph", "iisph"}) {
    SCOPED_TRACE(solver);
    auto doc = small_dam_break(solver);
    doc["materials"]["water"]["surface_tension"] = 0.5;
    doc["materials"]["water"]["adhesion"] = {{"walls", 1.0}};
    expect_same_as_one_rank(doc, 60);
  }
}

// The continuum surface force reads its neighbours' fitted curvatures: a second field the ghosts
// carry, written by a stage of its own.
TEST(SplitWorld, ContinuumSurfaceForceIsBitwiseTheOneRankRun) {
  auto doc = small_dam_break("dfsph");
  doc["materials"]["water"]["surface_tension"] = 0.5;
  doc["materials"]["water"]["surface_tension_model"] = "csf";
  expect_same_as_one_rank(doc, 60);
}

// Implicit viscosity: the conjugate gradient reads its neighbours' search directions (fields the
// ghosts carry) and steers by exact global dot products, so its iteration counts and its bits are
// the one-rank run's; the no-slip walls' velocities come from liquid on other ranks too.
TEST(SplitWorld, ImplicitViscosityIsBitwiseTheOneRankRun) {
  for (const std::string solver : {"pcisph", "dfsph"}) {
    SCOPED_TRACE(solver);
    auto doc = small_dam_break(solver);
    doc["materials"]["water"]["viscosity"] = 0.05;
    doc["materials"]["water"]["boundary_viscosity"] = 0.05;
    doc["materials"]["water"]["implicit_viscosity"] = 1;
    expect_same_as_one_rank(doc, 60);
  }
}

// DFSPH and IISPH checked against densities summed at the predicted positions
// (dfsph_summed_density.h, iisph_solve.h): the ghosts carry the predicted positions, and the
// rounds steer by global stopping errors; in a periodic domain the images carry them shifted.
TEST(SplitWorld, SummedDensityChecksAreBitwiseTheOneRankRun) {
  for (const std::string solver : {"dfsph", "iisph"}) {
    SCOPED_TRACE(solver);
    auto doc = small_dam_break(solver);
    doc["materials"]["water"]["solver"]["summed_density_check"] = 1;
    expect_same_as_one_rank(doc, 60);
    auto periodic = testing::periodic_dam_break(solver);
    periodic["materials"]["water"]["solver"]["summed_density_check"] = 1;
    expect_same_as_one_rank(periodic, 40);
  }
}

// Two liquids of different density (density_contrast.h): ghosts carry their masses and materials.
TEST(SplitWorld, DensityContrastIsBitwiseTheOneRankRun) {
  for (const std::string solver : {"pcisph", "iisph"})
    expect_same_as_one_rank(testing::oil_on_water_dam_break(solver, solver == "pcisph"), 60);
}

// A periodic domain across ranks: the ranks' ghosts include the periodic images, sent to the
// rank (this one too) that holds the place they land on, so the bits are the one-process run's
// (periodic_domain.h), through a checkpoint too.
TEST(SplitWorld, PeriodicDomainIsBitwiseTheOneRankRun) {
  expect_same_as_one_rank(testing::periodic_dam_break(), 150);
  expect_same_as_one_rank(testing::periodic_dam_break("dfsph"), 60, 10, 30);
}

TEST(SplitWorld, RebalancingEveryStepOrNeverChangesNoBit) {
  expect_same_as_one_rank(small_dam_break(), 80, 1);
  expect_same_as_one_rank(small_dam_break(), 80, 0);
}

// The domain cuts weigh a particle by the work it costs (mpi_domain.cpp): walls, which no solver
// queries or moves, count a tenth of a liquid particle. Counted as one each, the walls around the
// dam break's empty part filled whole shares: at 2 ranks one rank owned 2,600 of the 3,000 liquid
// particles and waited for nothing while the other waited for it (bench_mpi_scaling, docs/mpi.md).
// The slowest rank sets the step, so the most liquid any rank owns after the first cut must stay
// within 1.4 times an even share (weights of one: 1.73, 1.8 and 1.9 times at 2, 3 and 4 ranks;
// a tenth: 1.0, 1.32, 1.32; the cuts fall between the coarse scene's particle layers).
TEST(SplitWorld, DomainsShareTheLiquidNotTheWalls) {
  const nlohmann::json doc = small_dam_break();
  testing::TestWorld tw(doc, 1);
  World& world = *tw.world;
  world.set_domain(std::make_unique<MpiDomain>(MPI_COMM_WORLD, world.settings().support_radius(),
                                               10, world.settings().periodic));
  world.step(world.next_time_step());
  const Particles& p = world.particles();
  std::int64_t counts[2] = {0, 0};  // liquid, walls owned here
  for (std::size_t i = 0; i < p.owned_size(); ++i)
    ++counts[p.type[i] == ParticleType::Liquid ? 0 : 1];
  std::vector<std::int64_t> all(2 * std::size_t(ranks_here()));
  MPI_Allgather(counts, 2, MPI_INT64_T, all.data(), 2, MPI_INT64_T, MPI_COMM_WORLD);
  std::int64_t liquid = 0, most = 0;
  std::string owned;
  for (int r = 0; r < ranks_here(); ++r) {
    const std::int64_t here = all[2 * std::size_t(r)];
    liquid += here;
    most = std::max(most, here);
    owned += "\n  rank " + std::to_string(r) + ": " + std::to_string(here) + " liquid, " +
             std::to_string(all[2 * std::size_t(r) + 1]) + " walls";
  }
  ASSERT_EQ(liquid, 3000) << "the scene's liquid, summed over the ranks";
  const double share = double(liquid) / ranks_here();
  EXPECT_LE(double(most), 1.4 * share)
      << "the most liquid a rank owns, against an even share of " << share << ":" << owned;
}

// The shipped sample, coarser, its meshes found from here.
nlohmann::json small_floating_objects() {
  auto doc = testing::load_sample_json("floating_objects.json");
  doc["particle_spacing"] = 0.04;
  for (auto& body : doc["bodies"]) {
    const std::string file = body["mesh"]["file"];
    body["mesh"]["file"] = testing::kTestMeshes + file.substr(file.rfind('/') + 1);
  }
  return doc;
}

TEST(SplitWorld, FloatingBodiesAreBitwiseTheOneRankRun) {
  expect_same_as_one_rank(small_floating_objects(), 100);
}

// Free-slip walls and bodies (framework/boundary/slip_normal.h): normals computed before the
// split, carried by the particles that migrate, turned with the floating bodies on every rank.
TEST(SplitWorld, FreeSlipWallsAndBodiesAreBitwiseTheOneRankRun) {
  auto doc = small_floating_objects();
  for (auto& [name, material] : doc["materials"].items()) {
    const std::string type = material["type"];
    if (type == "liquid") material["boundary_viscosity"] = 0.01;
    if (type == "frozen" || type == "rigid") material["free_slip"] = 1;
  }
  expect_same_as_one_rank(doc, 100);
}

// Frozen bodies' reactions (solvers/fluid/boundary_reactions.h): a fixed block and a paddle
// turning across the cuts, with the wall pressure, whose per-particle factors the ranks take from
// their ghosts' owners.
TEST(SplitWorld, FixedAndTurningObstaclesAreBitwiseTheOneRankRun) {
  auto doc = small_dam_break();
  testing::add_fixed_block_and_paddle(doc);
  expect_same_as_one_rank(doc, 130);  // the surge reaches the paddle at about step 110
}

// Grains: pairs across a domain face are computed on both ranks, and the springs follow the
// grains that migrate (dem_contact_list.h). The sample scene, coarser, with a smaller block of
// sand just above the water, across the domains' cuts: grains in air, grains in water (drag and
// buoyancy both ways), on the floor and the walls, and against the floating boxes.
nlohmann::json small_sand_into_water() {
  auto doc = testing::load_sample_json("sand_into_water.json");
  doc["particle_spacing"] = 0.04;
  doc["granular_blocks"][0]["min"] = {0.42, 0.31, 0.14};
  doc["granular_blocks"][0]["max"] = {0.58, 0.4, 0.26};
  for (auto& body : doc["bodies"]) {
    const std::string file = body["mesh"]["file"];
    body["mesh"]["file"] = testing::kTestMeshes + file.substr(file.rfind('/') + 1);
  }
  return doc;
}

// A column of grains pushed over by a tilted gravity, flowing along the tank across the cuts:
// long-lived contacts (a pile) whose grains migrate, and the walls' force table. (Upright, the
// stacked column stands still.)
nlohmann::json small_granular_column(const std::string& model) {
  auto doc = testing::load_sample_json("granular_column.json");
  doc["containers"][0]["max"] = {0.5, 0.24, 0.1};
  doc["granular_blocks"][0]["min"] = {0.1, 0, 0};
  doc["granular_blocks"][0]["max"] = {0.22, 0.2, 0.1};
  doc["gravity"] = {5, -9.81, 0};
  doc["materials"]["sand"]["solver"] = {{"name", model}};
  return doc;
}

TEST(SplitWorld, SandIntoWaterIsBitwiseTheOneRankRun) {
  expect_same_as_one_rank(small_sand_into_water(), 100);
}

TEST(SplitWorld, CollapsingGrainColumnsAreBitwiseTheOneRankRun) {
  // Rebalanced every 5 steps: the domains move under the pile, and its springs with them.
  expect_same_as_one_rank(small_granular_column("dem_linear"), 120, 5);
  expect_same_as_one_rank(small_granular_column("dem_hertz"), 60, 1);
}

TEST(SplitWorld, GrainSpringsSurviveASplitCheckpoint) {
  // The gathered springs, restored on every rank, continue as if nothing happened.
  expect_same_as_one_rank(small_granular_column("dem_linear"), 100, 5, 50);
}

// Emitters and sinks (issue 40): every rank runs every source alike, keeps the emitted
// particles its domain owns (so the ids are the one-rank run's) and removes what its share of the
// sink holds; through a checkpoint taken mid-pour. A hose pours into a small tank whose floor is
// half drain, across the ranks' cuts.
TEST(SplitWorld, APourIntoADrainIsBitwiseTheOneRankRun) {
  nlohmann::json doc = testing::hose_into_a_drain();
  doc["neighbours"] = {{"reorder_every", 0}};
  Outcome split;
  expect_same_as_one_rank(doc, 90, 10, 45, &split);
  if (rank_here() == 0) {
    EXPECT_GT(split.added, 300u) << "the hose poured";
    EXPECT_GT(split.removed, 20u) << "the drain took some of it";
    std::printf("poured %zu, drained %zu\n", split.added, split.removed);
  }
}

// Open ends (issue 40): the outlet's outflow buffer sums the speeds arriving over every rank
// (exactly, in integers), so each rank imposes the one-rank run's speeds on its share.
TEST(SplitWorld, AChannelWithOpenEndsIsBitwiseTheOneRankRun) {
  nlohmann::json doc = testing::channel_with_open_ends();
  doc["neighbours"] = {{"reorder_every", 0}};
  Outcome split;
  expect_same_as_one_rank(doc, 120, 10, 60, &split);
  if (rank_here() == 0) {
    EXPECT_GT(split.added, 300u) << "the inlet poured";
    EXPECT_GT(split.removed, 20u) << "the outlet took some of it";
  }
}

// Particle reuse: the drain gives back what every rank took, so every rank's hose places the
// one-rank run's layers once its budget is full.
TEST(SplitWorld, APourThatReusesItsParticlesIsBitwiseTheOneRankRun) {
  nlohmann::json doc = testing::hose_into_a_drain();
  doc["neighbours"] = {{"reorder_every", 0}};
  doc["emitters"][0]["name"] = "hose";
  doc["emitters"][0]["max_particles"] = 300;
  doc["emitters"][0]["at_limit"] = "reuse";
  doc["sinks"][0]["reuse"] = "hose";
  Outcome split;
  expect_same_as_one_rank(doc, 150, 10, 75, &split);
  if (rank_here() == 0) {
    EXPECT_GT(split.added, 320u) << "the hose poured on past its budget";
    EXPECT_GT(split.removed, 20u);
  }
}

// What the split world cannot run yet is refused before any step, on every rank alike.
void expect_refused(const nlohmann::json& doc, const std::string& needle) {
  try {
    run(doc, 1, true);
    ADD_FAILURE() << "the scene ran across ranks";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(SplitWorld, PercentileStoppingTestsAreRefused) {
  if (ranks_here() == 1) GTEST_SKIP() << "one rank runs them as usual";
  auto percentile = small_dam_break();
  percentile["materials"]["water"]["solver"] = {{"name", "pcisph"}, {"stop_percentile", 50}};
  expect_refused(percentile, "stop_percentile 50");
}

}  // namespace
}  // namespace upf

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  // Rank 0 reports; the others' failures still fail the run through their exit code.
  if (upf::rank_here() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS();
  MPI_Finalize();
  return failed;
}
