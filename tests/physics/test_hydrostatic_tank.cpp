// Hydrostatic tank with PCISPH (samples/hydrostatic_tank.json, eta = 0.5 %): water at rest must
// hold the hydrostatic pressure p = rho0 g d at depth d (Pascal's law), stay nearly incompressible
// (Solenthaler & Pajarola 2009: average compression below eta), come to rest, and stay inside the
// tank (Akinci et al. 2012 boundaries).
#include <gtest/gtest.h>

#include <cmath>

#include "tank_checks.h"

namespace upf {
namespace {

TEST(HydrostaticTank, PcisphHoldsHydrostaticPressureAtRest) {
  testing::TestWorld tw(testing::load_sample_json("hydrostatic_tank.json"), 2);
  const double rho0 = 1000, g = 9.81;
  // Settle for 1.5 s, then average the pressure over 0.25 s.
  const testing::TankAtRest r = testing::measure_tank_at_rest(tw, rho0, 1.5, 0.25);
  const World& w = *tw.world;
  const MaterialId water = *w.materials().find("water");
  const double eta = w.materials()[water].solver_params.get("eta");

  // Density error after settling: the solver's average (its stopping measure) and the largest
  // compression of the SPH density at the particles' positions, reported apart for the tank
  // edges and corners, where compression is largest.
  const SolverStats stats = w.last_step().solver;
  std::printf("avg density error %.5f, max %.5f (at tank edges %.5f), iterations %d\n",
              stats.avg_density_error, r.max_compression, r.max_compression_edges,
              stats.iterations);
  EXPECT_LT(stats.avg_density_error, eta);
  EXPECT_LT(std::max(r.max_compression, r.max_compression_edges), 0.03);

  // Free surface: the top particles + half a spacing, against the block's height.
  EXPECT_NEAR(r.surface, r.column, 0.05 * r.column) << "water level";

  // RMS velocity below 1 % of sqrt(g H).
  std::printf("v_rms %.5f m/s, limit %.5f\n", r.v_rms, 0.01 * std::sqrt(g * r.column));
  EXPECT_LT(r.v_rms, 0.01 * std::sqrt(g * r.column));

  // Pressure at depth d >= 2 support radii, averaged over a horizontal slab one spacing thick,
  // away from the side walls: within 5 % of rho0 g d.
  ASSERT_FALSE(r.pressure_by_depth.empty());
  for (const auto& [depth, measured] : r.pressure_by_depth) {
    const double expected = rho0 * g * depth;
    std::printf("depth %.3f m: p = %.1f Pa, rho0 g d = %.1f Pa (%+.2f %%)\n", depth, measured,
                expected, 100 * (measured - expected) / expected);
    EXPECT_NEAR(measured, expected, 0.05 * expected) << "depth " << depth;
  }

  // Every particle inside the tank (not past the first wall layer, half a spacing out).
  EXPECT_FALSE(r.outside) << "particle " << w.particles().id[r.outside.value_or(0)]
                          << " left the tank";
}

}  // namespace
}  // namespace upf
