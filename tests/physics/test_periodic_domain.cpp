// A periodic domain has no preferred origin (periodic_box.h): a water column that straddles the
// face x = 0 (two fluid blocks, [0, 0.32] and [1.28, 1.6] in a period of 1.6 m, 8 spacings each)
// is the same column as one in the middle of the period ([0.48, 1.12]), and must collapse alike.
// Every solver stage that reads a neighbour's position through an image (PCISPH's predicted
// positions, the walls' extrapolated pressure, the viscosity) is exercised by the straddling one;
// the reference is the unbroken one (translation invariance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

struct Collapse {
  double kinetic_energy = 0;     // J at the end
  double front = 0;              // m: how far the column's liquid reached from its centre plane
  double max_density_error = 0;  // the largest over every step
};

Collapse collapse(const std::string& solver, bool straddling) {
  auto doc = periodic_dam_break(solver);
  if (straddling)
    doc["fluid_blocks"] = {
        {{"material", "water"}, {"min", {0, 0, 0}}, {"max", {0.32, 0.8, 0.4}}},
        {{"material", "water"}, {"min", {1.28, 0, 0}}, {"max", {1.6, 0.8, 0.4}}}};
  else
    doc["fluid_blocks"] = {
        {{"material", "water"}, {"min", {0.48, 0, 0}}, {"max", {1.12, 0.8, 0.4}}}};
  const double centre = straddling ? 0 : 0.8;
  TestWorld t(doc, 2);
  Collapse out;
  while (t.world->time() < 0.25 - 1e-12) {
    t.world->step(t.world->next_time_step_until(0.25));
    out.max_density_error =
        std::max(out.max_density_error, t.world->last_step().solver.max_density_error);
  }
  out.kinetic_energy = t.world->kinetic_energy();
  const Particles& p = t.world->particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    double dx = std::abs(double(p.position[i].x) - centre);
    dx = std::min(dx, 1.6 - dx);  // across the face
    out.front = std::max(out.front, dx);
  }
  return out;
}

TEST(PeriodicDomain, AColumnAcrossTheFaceCollapsesAsTheSameColumnInsideThePeriod) {
  for (const std::string solver : {"pcisph", "dfsph", "iisph", "wcsph"}) {
    SCOPED_TRACE(solver);
    const Collapse inside = collapse(solver, false), across = collapse(solver, true);
    std::printf(
        "%s, 0.25 s: kinetic energy %.3f J inside, %.3f J across the face (%+.2f %%); front "
        "%.3f / %.3f m; largest density error %.2f / %.2f %%\n",
        solver.c_str(), inside.kinetic_energy, across.kinetic_energy,
        100 * (across.kinetic_energy / inside.kinetic_energy - 1), inside.front, across.front,
        100 * inside.max_density_error, 100 * across.max_density_error);
    if (solver == "pcisph")
      record_validation(
          "periodic domain: kinetic energy at 0.25 s of a collapsing column across the face, "
          "over the same column inside the period",
          "translation invariance", "1", "within 2 %",
          across.kinetic_energy / inside.kinetic_energy);
    EXPECT_NEAR(across.kinetic_energy / inside.kinetic_energy, 1, 0.02);
    EXPECT_NEAR(across.front, inside.front, 0.04);  // one spacing
    EXPECT_LT(across.max_density_error, 1.5 * inside.max_density_error + 0.005);
  }
}

}  // namespace
}  // namespace upf::testing
