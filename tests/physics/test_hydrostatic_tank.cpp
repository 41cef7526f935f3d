// Hydrostatic tank (samples/hydrostatic_tank.json): water at rest must hold the hydrostatic
// pressure p = rho0 g d at depth d (Pascal's law), stay nearly incompressible and stay inside the
// tank (Akinci et al. 2012 boundaries). One test per fluid solver, measured alike
// (hydrostatic_tank.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hydrostatic_tank.h"
#include "validation_record.h"

namespace upf {
namespace {

using testing::HydrostaticTankResult;
using testing::kTankColumn;

void expect_inside_tank(const HydrostaticTankResult& r) {
  EXPECT_TRUE(r.all_inside) << "a particle left the tank";
}

// Pascal's law down to the floor: every lattice layer at least 2.5 support radii (10 cm) below
// the surface, the one on the floor included (what a floor pressure sensor reads), within 5 % of
// rho0 g d. Nearer the surface the kernel sum is deficient and the layers read up to 6 % high
// (PCISPH) with or without walls. With Akinci et al.'s boundary term alone the floor layer read
// +72 % (PCISPH; boundary_pressure.h).
void expect_hydrostatic_to_the_floor(const HydrostaticTankResult& r, double support) {
  int checked = 0;
  double worst = 0;
  for (const auto& l : r.layers) {
    ASSERT_GT(l.particles, 0) << "layer " << l.layer;
    if (r.surface - l.height < 2.5 * support) continue;
    EXPECT_NEAR(l.measured, l.expected, 0.05 * l.expected)
        << "layer " << l.layer << " at y = " << l.height << " m";
    worst = std::max(worst, std::abs(l.relative_error()));
    ++checked;
  }
  EXPECT_GE(checked, int(r.layers.size()) - 6);
  ASSERT_FALSE(r.layers.empty());
  testing::record_validation("floor layer pressure / rho0 g d (time-averaged)",
                             "Pascal's law, hydrostatic", "1", "within 5 %",
                             r.layers.front().measured / r.layers.front().expected);
  testing::record_validation("largest layer deviation from rho0 g d, 10 cm below the surface down",
                             "Pascal's law, hydrostatic", "0", "below 5 %", worst);
  EXPECT_GT(r.layers.front().height, 0.25 * kTankColumn / double(r.layers.size()))
      << "the floor layer sank from its lattice height towards the floor";
}

// The iterative solvers at the sample's 2 cm: settle for 1.5 s, then average the pressure over
// 0.25 s (their pressures are re-solved every step and flicker from step to step, as a pressure
// sensor's reading would be averaged). Average compression below eta, largest below 3 %, the
// water level kept, rest (RMS velocity below 1 % of sqrt(g H)), every slab hydrostatic within 5 %.
HydrostaticTankResult expect_incompressible_tank(const nlohmann::json& doc, double eta,
                                                 double average_time = 0.25) {
  const HydrostaticTankResult r = testing::run_hydrostatic_tank(doc, 2, 1.5, average_time);
  testing::print_hydrostatic_tank(r);
  EXPECT_LT(r.last_step.avg_density_error, eta);
  EXPECT_LT(std::max(r.max_error, r.max_error_edges), 0.03);
  EXPECT_NEAR(r.surface, kTankColumn, 0.05 * kTankColumn) << "water level";
  EXPECT_LT(r.v_rms, 0.01 * std::sqrt(9.81 * kTankColumn));
  // Against rho0 g d at the slab's particles' mean depth: a slab one spacing thick catches a
  // lattice layer up to half a spacing off its nominal depth (10 mm, 12 % of the pressure at
  // 0.08 m), which the comparison at the nominal depth counted as error.
  for (const auto& s : r.slabs) {
    EXPECT_GT(s.particles, 0);
    EXPECT_NEAR(s.measured, s.expected_at_particles, 0.05 * s.expected_at_particles)
        << "depth " << s.depth;
  }
  expect_inside_tank(r);
  return r;
}

// PCISPH (Solenthaler & Pajarola 2009), the sample as shipped (eta = 0.5 %).
TEST(HydrostaticTank, PcisphHoldsHydrostaticPressureAtRest) {
  const auto doc = testing::load_sample_json("hydrostatic_tank.json");
  expect_incompressible_tank(doc, doc["materials"]["water"]["solver"]["eta"]);
}

// PCISPH with the wall pressure (boundary_pressure.h) at the sample's eta: hydrostatic to the
// floor. Averaged over 1 s: PCISPH's pressure is the sum of its corrections, so a step that ends
// after 3, 4 or 5 iterations exports about 3/4, 1 or 5/4 of the mean (the probe at 0.39 m read
// 2790, 3730 or 4690 Pa), and the mean over 0.25 s depends on that mix by about 5 %.
TEST(HydrostaticTank, PcisphWithWallPressureIsHydrostaticToTheFloor) {
  auto doc = testing::load_sample_json("hydrostatic_tank.json");
  doc["materials"]["water"]["solver"]["wall_pressure"] = 1;
  const auto r = expect_incompressible_tank(doc, doc["materials"]["water"]["solver"]["eta"], 1.0);
  expect_hydrostatic_to_the_floor(r, 0.04);
}

// Density error at rest below eta everywhere: with the stopping test on the largest compression
// (stop_percentile 100) instead of the average, and the wall pressure, no particle of the tank
// (walls and edges included) is compressed by eta or more at the last step, nor on average over
// the last second; the layers stay hydrostatic to the floor. PCISPH at the sample's eta, IISPH
// and DFSPH at 0.2 % (the wall pressure's tolerance for them).
void expect_every_particle_below_eta(const std::string& solver, double eta,
                                     const std::string& reference) {
  auto doc = testing::load_sample_json("hydrostatic_tank.json");
  doc["materials"]["water"]["solver"] = {
      {"name", solver}, {"eta", eta}, {"wall_pressure", 1}, {"stop_percentile", 100}};
  const auto r = expect_incompressible_tank(doc, eta, 1.0);
  testing::record_validation("largest compression at rest / eta, stop_percentile 100", reference,
                             "below 1", "below 1", std::max(r.max_error, r.max_error_edges) / eta);
  EXPECT_LT(std::max(r.max_error, r.max_error_edges), eta);
  EXPECT_LT(r.max_mean_density_error, eta);
  expect_hydrostatic_to_the_floor(r, 0.04);
}

TEST(HydrostaticTank, PcisphBoundingTheLargestCompressionKeepsEveryParticleBelowEta) {
  const auto doc = testing::load_sample_json("hydrostatic_tank.json");
  expect_every_particle_below_eta("pcisph", doc["materials"]["water"]["solver"]["eta"],
                                  "PCISPH's stopping test (Solenthaler & Pajarola 2009)");
}

TEST(HydrostaticTank, IisphBoundingTheLargestCompressionKeepsEveryParticleBelowEta) {
  expect_every_particle_below_eta("iisph", 0.002, "IISPH's stopping test (Ihmsen et al. 2014)");
}

TEST(HydrostaticTank, DfsphBoundingTheLargestCompressionKeepsEveryParticleBelowEta) {
  expect_every_particle_below_eta("dfsph", 0.002, "DFSPH's stopping test (Bender & Koschier 2017)");
}

// Without it, the floor layer sinks and reads far above rho0 g d: what the wall pressure fixes.
TEST(HydrostaticTank, PcisphWithAkincisTermAloneReadsTooHighOnTheFloor) {
  const auto doc = testing::load_sample_json("hydrostatic_tank.json");
  const HydrostaticTankResult r = testing::run_hydrostatic_tank(doc, 2, 1.5, 0.25);
  ASSERT_FALSE(r.layers.empty());
  std::printf("floor layer at %.4f m: %.3f rho0 g d\n", r.layers.front().height,
              r.layers.front().measured / r.layers.front().expected);
  testing::record_validation("floor layer pressure / rho0 g d, Akinci's boundary term alone",
                             "Pascal's law: the defect wall_pressure fixes", "1", "above 1.5",
                             r.layers.front().measured / r.layers.front().expected);
  EXPECT_GT(r.layers.front().measured, 1.5 * r.layers.front().expected);
}

// An implicit solver with the wall pressure turned on, at eta = 0.2 %: at 0.5 % its wall layer
// kept oscillating (kinetic energy 0.01-0.03 J against 0.0005 J; boundary_pressure.h). DFSPH's
// exported pressure (K rho^2 summed over both of its solves) reads its largest deviation, +2.3 %,
// on layer 3.
void expect_hydrostatic_to_the_floor_with(const std::string& solver) {
  auto doc = testing::load_sample_json("hydrostatic_tank.json");
  doc["materials"]["water"]["solver"] = {{"name", solver}, {"eta", 0.002}, {"wall_pressure", 1}};
  const auto r = expect_incompressible_tank(doc, 0.002, 0.5);
  expect_hydrostatic_to_the_floor(r, 0.04);
}

// IISPH (Ihmsen et al. 2014) with the wall pressure.
TEST(HydrostaticTank, IisphWithWallPressureIsHydrostaticToTheFloor) {
  expect_hydrostatic_to_the_floor_with("iisph");
}

// DFSPH (Bender & Koschier 2017) with the wall pressure.
TEST(HydrostaticTank, DfsphWithWallPressureIsHydrostaticToTheFloor) {
  expect_hydrostatic_to_the_floor_with("dfsph");
}

// The sample with its liquid moved by `solver` at PCISPH's eta.
void expect_incompressible_tank_with(const std::string& solver) {
  auto doc = testing::load_sample_json("hydrostatic_tank.json");
  const double eta = doc["materials"]["water"]["solver"]["eta"];
  doc["materials"]["water"]["solver"] = {{"name", solver}, {"eta", eta}};
  expect_incompressible_tank(doc, eta);
}

// DFSPH (Bender & Koschier 2017).
TEST(HydrostaticTank, DfsphHoldsHydrostaticPressureAtRest) {
  expect_incompressible_tank_with("dfsph");
}

// IISPH (Ihmsen et al. 2014).
TEST(HydrostaticTank, IisphHoldsHydrostaticPressureAtRest) {
  expect_incompressible_tank_with("iisph");
}

// The weakly compressible solvers at 2.5 cm spacing (the sample's 2 cm needs 1.6x the steps and
// 2x the particles), one thread (CI runs two tests at once on two cores). Started from rho0
// everywhere, the column keeps ringing at its acoustic mode (period about 4 H / c = 0.06-0.08 s,
// barely damped), so pressures are averaged over 0.5-1 s after 0.5 s.
HydrostaticTankResult run_state_equation_tank(const nlohmann::json& solver, double average_time) {
  const auto doc = testing::hydrostatic_tank_with(solver, 0.025);
  const HydrostaticTankResult r =
      testing::run_hydrostatic_tank(doc, 1, 0.5, average_time, testing::SurfaceReference::TopLayer);
  testing::print_hydrostatic_tank(r);
  return r;
}

// One pressure evaluation per step, average compression below 1 %, the water level kept, and
// every slab's pressure within `tolerance` of factor * rho0 g d at its particles' depths.
void expect_state_equation_tank(const HydrostaticTankResult& r, double factor, double tolerance) {
  EXPECT_EQ(r.last_step.iterations, 1);
  EXPECT_LT(r.last_step.avg_density_error, 0.01);
  EXPECT_NEAR(r.surface, kTankColumn, 0.05 * kTankColumn) << "water level";
  for (const auto& s : r.slabs) {
    ASSERT_GT(s.particles, 0);
    const double expected = factor * s.expected_at_particles;
    EXPECT_NEAR(s.measured, expected, tolerance * expected) << "depth " << s.depth;
  }
  expect_inside_tank(r);
}

// WCSPH (Becker & Teschner 2007): with c = 10 sqrt(2 g H) the Tait equation keeps the density
// within about 1 %, and the time-averaged pressure is hydrostatic within 5 %.
TEST(HydrostaticTank, WcsphHoldsHydrostaticPressure) {
  expect_state_equation_tank(run_state_equation_tank({{"name", "wcsph"}}, 1.0), 1, 0.05);
}

// WCSPH with the wall pressure (boundary_pressure.h): hydrostatic to the floor. Its walls reflect
// the column's ringing instead of absorbing it, so it rings longer (docs/boundary-pressure.md).
TEST(HydrostaticTank, WcsphWithWallPressureIsHydrostaticToTheFloor) {
  const auto r = run_state_equation_tank({{"name", "wcsph"}, {"wall_pressure", 1}}, 1.0);
  expect_state_equation_tank(r, 1, 0.05);
  expect_hydrostatic_to_the_floor(r, 0.05);
}

// SPH (Müller et al. 2003), defaults: cubic spline, k = 2 (10 sqrt(2 g H))^2. The paper's
// symmetrised pressure force is half the SPH pressure gradient in the bulk, so the water holds
// p = 2 rho0 g d (the bound asserted: within 10 % of that) and compresses by 2 g d / k, 0.5 % at
// the bottom.
TEST(HydrostaticTank, SphHoldsTwiceTheHydrostaticPressure) {
  expect_state_equation_tank(run_state_equation_tank({{"name", "sph"}}, 0.5), 2, 0.10);
}

// SPH with the paper's kernels (poly6, spiky, viscosity kernel) and the paper's viscosity at
// mu = 20 Pa s: the water stays near rest and in the tank. Without the viscosity the same run
// heats up without bound (sph_solver.h: kinetic energy 250 J at 1.1 s, 980 J at 1.8 s), so this
// fails if the kernel set's energy leak grows or the viscosity stops acting. 5 cm spacing: a
// stability check, not a pressure measurement.
TEST(HydrostaticTank, SphWithPaperKernelsStaysNearRestWithItsViscosity) {
  const auto doc = testing::hydrostatic_tank_with(
      {{"name", "sph"}, {"cubic_spline", 0}, {"viscosity", 20}}, 0.05);
  testing::TestWorld tw(doc, 1);
  World& w = *tw.world;
  const Particles& p = w.particles();
  auto kinetic_energy = [&] {
    double e = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      e += 0.5 * double(p.mass[i]) * double(squared_norm(p.velocity[i]));
    return e;
  };
  tw.run_until(1.0);
  double max_energy = 0;  // over the second second
  while (w.time() < 2.0 - 1e-12) {
    w.step(w.next_time_step_until(2.0));
    max_energy = std::max(max_energy, kinetic_energy());
  }
  const SolverStats stats = w.last_step().solver;
  std::printf("max kinetic energy in [1, 2] s: %.3f J, avg density error %.5f\n", max_energy,
              stats.avg_density_error);
  // 45 kg of water: 1 J is an rms speed of 0.2 m/s.
  EXPECT_LT(max_energy, 1.0);
  EXPECT_LT(stats.avg_density_error, 0.02);
  const double h = tw.scene.world.spacing;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const Vec3& x = p.position[i];
    ASSERT_TRUE(x.x > -0.5 * h && x.x < 0.3 + 0.5 * h && x.y > -0.5 * h && x.y < 0.7 + 0.5 * h &&
                x.z > -0.5 * h && x.z < 0.3 + 0.5 * h)
        << "particle " << p.id[i] << " left the tank";
  }
}

}  // namespace
}  // namespace upf
