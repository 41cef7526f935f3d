// The stage contract (DESIGN.md, "Stages, executors and backends"; framework/solver/stage_runner.h,
// framework/executors/cpu/cpu_executor.h): the world times the stages a solver declared, under
// those names only; the executor's reductions give the same answer for any thread count and any
// memory order, which is what makes every solver's results bitwise reproducible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/executors/cpu/cpu_executor.h"
#include "framework/solver/stage_runner.h"
#include "framework/world/world.h"

namespace upf {
namespace {

TEST(StageRunner, RefusesAStageItsSolverDidNotDeclare) {
  StageRunner run({"predict", "correct"});
  int calls = 0;
  run("predict", [&] { ++calls; });
  EXPECT_THROW(run("integrate", [&] { ++calls; }), std::logic_error);
  EXPECT_EQ(calls, 1) << "an undeclared stage must not run";
}

TEST(StageRunner, AStageRunTwiceInAStepIsOneColumn) {
  StageRunner run({"a", "b"});
  run("b", [] {});
  run("a", [] {});
  run("b", [] {});
  EXPECT_EQ(run.names(), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(run.ms().size(), 2u);
  run.clear();
  EXPECT_EQ(run.ms(), (std::vector<double>{0.0, 0.0}));
}

// A particle stage that writes i * i into out[i].
struct SquareStage {
  double* out;
  void operator()(std::uint32_t i) const { out[i] = double(i) * double(i); }
};

TEST(CpuExecutor, RunsAStageOverTheListedParticlesOnly) {
  std::vector<double> out(10, -1.0);
  const std::vector<std::uint32_t> listed = {7, 2, 9};
  CpuExecutor(2).run(ParticleRange{listed.data(), listed.size()}, SquareStage{out.data()});
  for (std::uint32_t i = 0; i < 10; ++i) {
    const bool is_listed = i == 2 || i == 7 || i == 9;
    EXPECT_EQ(out[i], is_listed ? double(i * i) : -1.0) << i;
  }
}

struct ValueAt {
  const double* v;
  double operator()(std::uint32_t i) const { return v[i]; }
};

struct Negative {
  const double* v;
  bool operator()(std::uint32_t i) const { return v[i] < 0; }
};

TEST(CpuExecutor, ReductionsAreTheSameForAnyThreadCount) {
  // Values spanning magnitudes, so a floating-point sum would depend on its order; the
  // fixed-point sum must not.
  std::vector<double> v(10007);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = double(std::int64_t(i * 2654435761u % 2001) - 1000) * (i % 3 == 0 ? 1e3 : 1e-3);
  std::vector<std::uint32_t> id(v.size());
  std::iota(id.begin(), id.end(), 0u);
  std::reverse(id.begin(), id.end());  // the smallest id is at the highest index
  const ParticleRange all = all_particles(v.size());
  const CpuExecutor one(1);
  const double sum1 = one.fixed_point_sum(all, ValueAt{v.data()});
  const double max1 = double(one.max_of(all, ValueAt{v.data()}, Real(-1e30)));
  const std::size_t first1 = one.first_by_id(v.size(), id.data(), Negative{v.data()});
  for (int threads : {2, 3, 8}) {
    const CpuExecutor exec(threads);
    EXPECT_EQ(exec.fixed_point_sum(all, ValueAt{v.data()}), sum1) << threads << " threads";
    EXPECT_EQ(double(exec.max_of(all, ValueAt{v.data()}, Real(-1e30))), max1) << threads;
    EXPECT_EQ(exec.first_by_id(v.size(), id.data(), Negative{v.data()}), first1) << threads;
  }
  // The first negative value in id order is the last negative one in index order; the maximum is
  // the serial one.
  std::size_t last_negative = v.size();
  Real serial_max = Real(-1e30);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] < 0) last_negative = i;
    serial_max = std::max(serial_max, Real(v[i]));
  }
  EXPECT_EQ(first1, last_negative);
  EXPECT_EQ(max1, double(serial_max));
}

TEST(CpuExecutor, FirstByIdIsNWhenNothingHolds) {
  const std::vector<double> v = {1, 2, 3};
  const std::vector<std::uint32_t> id = {0, 1, 2};
  EXPECT_EQ(CpuExecutor(2).first_by_id(3, id.data(), Negative{v.data()}), 3u);
}

// A solver with two stages, one of them run twice per step (as DEM's sub-steps do).
class TwoStageSolver final : public Solver {
 public:
  std::string_view name() const override { return "two_stage"; }
  void prepare(World&) override {}
  Real max_time_step(const World&) const override { return Real(1); }
  std::vector<std::string> stages() const override { return {"forces", "integration"}; }
  void step(World&, Real, StageRunner& run) override {
    for (int k = 0; k < 2; ++k) {
      run("forces", [] {});
      run("integration", [] {});
    }
  }
  SolverStats stats() const override { return {}; }
};

TEST(WorldStages, TheReportedStagesAreTheDeclaredListInEveryStep) {
  WorldSettings settings;
  settings.time.fixed_dt = 0.001;
  World world(settings, 1);
  world.particles().add({0, 0, 0}, {}, 1, ParticleType::Liquid, 0);
  world.add_solver(std::make_unique<TwoStageSolver>());
  world.prepare();
  EXPECT_EQ(world.stage_names(), (std::vector<std::string>{"forces", "integration"}));
  for (int step = 0; step < 3; ++step) {
    world.step(0.001);
    std::vector<std::string> reported;
    for (const auto& [name, ms] : world.last_step().stage_ms) reported.push_back(name);
    EXPECT_EQ(reported, world.stage_names()) << "step " << step;
  }
}

}  // namespace
}  // namespace upf
