// Typed solver parameters (framework/params/param_binding.h): one table binds each spec to a
// member, so what the scene reader checks, `upf info` lists and the solver reads are the same.
#include "framework/params/param_binding.h"

#include <gtest/gtest.h>

#include "solvers/pcisph/pcisph_solver.h"

namespace upf {
namespace {

struct Example {
  double gain = 0;
  int count = 0;
  bool enabled = false;
};

ParamBinding<Example> example_binding() {
  ParamBinding<Example> b;
  b.add({"gain", "1", 0.5, 0, 2, "a real number"}, &Example::gain);
  b.add({"count", "1", 3, 1, 10, "a whole number"}, &Example::count);
  b.add({"enabled", "1", 1, 0, 1, "a switch"}, &Example::enabled);
  return b;
}

TEST(ParamBinding, SpecsKeepTheTableOrderAndMarkWholeNumbersAndSwitches) {
  const auto specs = example_binding().specs();
  ASSERT_EQ(specs.size(), 3u);
  EXPECT_EQ(specs[0].name, "gain");
  EXPECT_FALSE(specs[0].integer);
  EXPECT_EQ(specs[1].name, "count");
  EXPECT_TRUE(specs[1].integer);
  EXPECT_EQ(specs[2].name, "enabled");
  EXPECT_TRUE(specs[2].integer);
  EXPECT_EQ(specs[2].min_value, 0);
  EXPECT_EQ(specs[2].max_value, 1);
}

TEST(ParamBinding, BindsDefaultsAndSceneValuesToTheMembers) {
  const auto binding = example_binding();
  ParamValues values(binding.specs());
  Example e = binding.bind(values);
  EXPECT_EQ(e.gain, 0.5);
  EXPECT_EQ(e.count, 3);
  EXPECT_TRUE(e.enabled);

  values.set("gain", 1.25);
  values.set("count", 7);
  values.set("enabled", 0);
  e = binding.bind(values);
  EXPECT_EQ(e.gain, 1.25);
  EXPECT_EQ(e.count, 7);
  EXPECT_FALSE(e.enabled);
}

TEST(ParamBinding, ValuesWithoutAMemberNameAreRefused) {
  // A ParamValues made for another table lacks the names: bind throws instead of reading zero.
  ParamValues other(std::vector<ParamSpec>{{"gian", "1", 0.5, 0, 2, "misspelt"}});
  EXPECT_THROW((void)example_binding().bind(other), std::out_of_range);
}

TEST(ParamBinding, PcisphReadsItsDocumentedDefaults) {
  const auto binding = PcisphSolver::param_binding();
  const PcisphParams p = binding.bind(ParamValues(binding.specs()));
  EXPECT_EQ(p.eta, 0.01);
  EXPECT_EQ(p.min_iterations, 3);
  EXPECT_EQ(p.max_iterations, 100);
}

}  // namespace
}  // namespace upf
