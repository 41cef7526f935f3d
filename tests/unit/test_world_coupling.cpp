// The coupling arrays and the solver order (framework/world/coupling.h, DESIGN.md "Boundaries
// and coupling"): every array is written before it is read, the given order is kept wherever the
// declarations allow, and a scene whose reads nobody writes, or whose declarations form a cycle,
// is refused with an error naming the solvers.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "framework/core/errors.h"
#include "framework/world/coupling.h"
#include "framework/world/world.h"

namespace upf {
namespace {

constexpr CouplingArray kBoundary = CouplingArray::BoundaryForce;
constexpr CouplingArray kLiquid = CouplingArray::LiquidForce;

std::string message_of(const InputError& e) {
  std::string all;
  for (const InputProblem& p : e.problems()) all += p.where + ": " + p.message + "\n";
  return all;
}

// The message of the InputError coupling_order throws for `solvers` (empty if it throws none).
std::string refusal_of(const std::vector<DeclaredSolver>& solvers) {
  try {
    coupling_order(solvers);
  } catch (const InputError& e) {
    return message_of(e);
  }
  return {};
}

TEST(CouplingOrder, WritersStepBeforeTheirReadersAndTheGivenOrderStaysElsewhere) {
  // A fluid listed before the grains whose drag it applies; a second fluid; the grains.
  const std::vector<DeclaredSolver> solvers = {
      {"fluid_a", {{kBoundary}, {}, {kLiquid}}},
      {"fluid_b", {{kBoundary}, {}, {kLiquid}}},
      {"grains", {{kBoundary, kLiquid}, {}, {}}},
  };
  EXPECT_EQ(coupling_order(solvers), (std::vector<std::size_t>{2, 0, 1}));
  // Writers of one array only (they add into it) keep their order.
  const std::vector<DeclaredSolver> writers = {{"b", {{kBoundary}, {}, {}}},
                                               {"a", {{kBoundary}, {}, {}}}};
  EXPECT_EQ(coupling_order(writers), (std::vector<std::size_t>{0, 1}));
}

TEST(CouplingOrder, AReadNobodyWritesIsRefusedNamingTheSolverAndTheArray) {
  const std::vector<DeclaredSolver> solvers = {{"pcisph", {{kBoundary}, {}, {kLiquid}}},
                                               {"needs_grains", {{}, {kLiquid}, {}}}};
  const std::string m = refusal_of(solvers);
  ASSERT_FALSE(m.empty()) << "no error";
  EXPECT_NE(m.find("'needs_grains'"), std::string::npos) << m;
  EXPECT_NE(m.find("'liquid_force'"), std::string::npos) << m;
  EXPECT_EQ(m.find("'pcisph'"), std::string::npos) << m;  // an optional read is no problem
}

TEST(CouplingOrder, ACycleIsRefusedNamingTheSolversInIt) {
  const std::vector<DeclaredSolver> solvers = {{"first", {{kBoundary}, {kLiquid}, {}}},
                                               {"bystander", {{}, {}, {}}},
                                               {"second", {{kLiquid}, {kBoundary}, {}}}};
  const std::string m = refusal_of(solvers);
  ASSERT_FALSE(m.empty()) << "no error";
  EXPECT_NE(m.find("'first'"), std::string::npos) << m;
  EXPECT_NE(m.find("'second'"), std::string::npos) << m;
  EXPECT_EQ(m.find("'bystander'"), std::string::npos) << m;
  EXPECT_NE(m.find("cycle"), std::string::npos) << m;
}

// A solver that records when it steps and what the coupling arrays held.
class RecordingSolver final : public Solver {
 public:
  RecordingSolver(std::string name, std::vector<std::string>* log) : name_(std::move(name)), log_(log) {}
  std::string_view name() const override { return name_; }
  void prepare(World&) override {}
  Real max_time_step(const World&) const override { return Real(1); }
  std::vector<std::string> stages() const override { return {"record"}; }
  void step(World& world, Real, StageRunner& run) override {
    run("record", [&] {
      log_->push_back(name_ + ":" + std::to_string(world.coupling()[kLiquid].size()));
    });
  }
  SolverStats stats() const override { return {}; }

 private:
  std::string name_;
  std::vector<std::string>* log_;
};

TEST(CouplingOrder, TheWorldStepsSolversInDeclaredOrderAndSizesTheActiveArrays) {
  WorldSettings settings;
  settings.time.fixed_dt = 0.001;
  World world(settings, 1);
  world.particles().add({0, 0, 0}, {}, 1, ParticleType::Liquid, 0);
  world.particles().add({1, 0, 0}, {}, 1, ParticleType::Granular, 0);
  std::vector<std::string> log;
  world.add_solver(std::make_unique<RecordingSolver>("fluid", &log), {{}, {}, {kLiquid}});
  world.add_solver(std::make_unique<RecordingSolver>("grains", &log), {{kLiquid}, {}, {}});
  world.prepare();
  world.step(0.001);
  EXPECT_EQ(log, (std::vector<std::string>{"grains:2", "fluid:2"}));
  EXPECT_EQ(world.solvers().front()->name(), "grains");
  // Nobody reads the boundary forces (no bodies, no reader): they stay empty.
  EXPECT_FALSE(world.coupling().active(kBoundary));
  EXPECT_TRUE(world.coupling()[kBoundary].empty());
}

TEST(CouplingOrder, WorldPrepareRefusesAReadWithoutAWriter) {
  World world(WorldSettings{}, 1);
  std::vector<std::string> log;
  world.add_solver(std::make_unique<RecordingSolver>("lonely", &log), {{}, {kLiquid}, {}});
  EXPECT_THROW(world.prepare(), InputError);
}

}  // namespace
}  // namespace upf
