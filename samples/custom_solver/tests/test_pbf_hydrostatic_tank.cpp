// Hydrostatic tank with PBF (samples/hydrostatic_tank.json, solver switched to pbf, default
// parameters). Macklin & Müller 2013 iterate the density constraint a fixed number of times (4),
// so the water is not held at a target compression as with PCISPH; the bounds below are those
// the sample's README.md documents:
//   - compression: the solver's average (PCISPH's definition) and the SPH density's average
//     below 1 %, the largest below 3 %;
//   - the water stands at its level (5 %), every particle stays inside the tank (Akinci et al.
//     2012 boundaries), and the water comes to rest: v_rms below 2 % of sqrt(g H) after 1 s (PBF
//     corrects only part of each step's fall in 4 iterations, so it jitters more than PCISPH);
//   - Pascal's law in the pressure equivalent to the corrections (pbf_solver.h,
//     p = -rho0 sum lambda / dt^2): dp/dd within 10 % of rho0 g. The top layer, whose clamped
//     constraint gives it no lambda, rests on the layer below and on the artificial pressure, so
//     p is offset by less than two layers of water (rho0 g 2 h).
#include <gtest/gtest.h>

#include <cmath>

#include "pbf_test_world.h"
#include "tests/physics/tank_checks.h"

namespace upf::pbf {
namespace {

TEST(PbfHydrostaticTank, SettlesWithBoundedCompression) {
  auto tw = testing::pbf_world(testing::with_pbf("hydrostatic_tank.json"), 2);
  const double rho0 = 1000, g = 9.81, h = tw.scene.world.spacing;
  const upf::testing::TankAtRest r = upf::testing::measure_tank_at_rest(tw, rho0, 1.0, 0.25);
  const World& w = *tw.world;

  // Compression: the solver's measure (the last iteration's predicted density, PCISPH's
  // definition) and the SPH density at the particles' positions at the start of the last step.
  const SolverStats stats = w.last_step().solver;
  const double max_error = std::max(r.max_compression, r.max_compression_edges);
  std::printf(
      "solver: avg density error %.5f, max %.5f, %d iterations; density field: avg %.5f, "
      "max %.5f (at tank edges %.5f)\n",
      stats.avg_density_error, stats.max_density_error, stats.iterations, r.avg_compression,
      r.max_compression, r.max_compression_edges);
  EXPECT_EQ(stats.iterations, 4);
  EXPECT_LT(stats.avg_density_error, 0.01);
  EXPECT_LT(r.avg_compression, 0.01);
  EXPECT_LT(std::max(max_error, stats.max_density_error), 0.03);

  std::printf("surface %.4f m (column %.2f m)\n", r.surface, r.column);
  EXPECT_NEAR(r.surface, r.column, 0.05 * r.column) << "water level";

  std::printf("v_rms %.5f m/s, limit %.5f\n", r.v_rms, 0.02 * std::sqrt(g * r.column));
  EXPECT_LT(r.v_rms, 0.02 * std::sqrt(g * r.column));

  // Pascal's law: a least-squares line p = a d + b through the slabs.
  double sd = 0, sp = 0, sdd = 0, sdp = 0;
  const double n = double(r.pressure_by_depth.size());
  ASSERT_GT(n, 2);
  for (const auto& [depth, p] : r.pressure_by_depth) {
    std::printf("depth %.3f m: p = %.1f Pa, rho0 g d = %.1f Pa\n", depth, p, rho0 * g * depth);
    sd += depth;
    sp += p;
    sdd += depth * depth;
    sdp += depth * p;
  }
  const double slope = (n * sdp - sd * sp) / (n * sdd - sd * sd);
  const double offset = (sp - slope * sd) / n;
  std::printf("dp/dd = %.0f Pa/m (rho0 g = %.0f), offset %.0f Pa (limit %.0f)\n", slope, rho0 * g,
              offset, rho0 * g * 2 * h);
  EXPECT_NEAR(slope, rho0 * g, 0.10 * rho0 * g);
  EXPECT_LT(std::abs(offset), rho0 * g * 2 * h);

  EXPECT_FALSE(r.outside) << "particle " << w.particles().id[r.outside.value_or(0)]
                          << " left the tank";
}

}  // namespace
}  // namespace upf::pbf
