// Plane Poiseuille flow (e.g. Batchelor, An Introduction to Fluid Dynamics, section 4.2): a
// liquid between two fixed no-slip walls a gap H apart, driven by a body force g along the walls,
// reaches u(y) = g y (H - y) / (2 nu). The channel repeats along x and z (a periodic domain,
// framework/world/periodic_box.h), so the flow has no ends: it tests the images across the faces
// as much as the viscosity. The viscosity is implicit (Weiler et al. 2018) at nu = 1 m^2/s, with a
// step far beyond the explicit viscosity's limit 0.070 s^2 / nu (docs/viscosity.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kSpacing = 0.01;  // m
constexpr double kGap = 0.2;       // m, H: 20 spacings between the walls' faces
constexpr double kPeriod = 0.06;   // m, along x and z: 6 spacings
constexpr double kNu = 1;          // m^2/s
constexpr double kForce = 10;      // m/s^2, g along x: u_max = g H^2 / (8 nu) = 5 cm/s
constexpr double kExplicitLimit = 0.070 * kSpacing * kSpacing / kNu;  // s

nlohmann::json channel_scene(double dt, const std::string& solver) {
  const nlohmann::json liquid = {{"type", "liquid"},
                                 {"density", 1000},
                                 {"viscosity", kNu},
                                 {"boundary_viscosity", kNu},
                                 {"implicit_viscosity", 1},
                                 {"viscosity_tolerance", 1e-6},
                                 {"viscosity_max_iterations", 1000},
                                 {"solver", solver}};
  return {{"name", "poiseuille"},
          {"gravity", {kForce, 0, 0}},
          {"particle_spacing", kSpacing},
          {"materials", {{"liquid", liquid}, {"walls", {{"type", "frozen"}}}}},
          {"periodic", {{"x", {0, kPeriod}}, {"z", {0, kPeriod}}}},
          {"containers",
           {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {kPeriod, kGap, kPeriod}}}}},
          {"fluid_blocks",
           {{{"material", "liquid"}, {"min", {0, 0, 0}}, {"max", {kPeriod, kGap, kPeriod}}}}},
          {"time", {{"fixed_dt", dt}}}};
}

double analytic(double y) {
  return kForce * y * (kGap - y) / (2 * kNu);
}

struct Profile {
  double worst = 0;   // the largest |u - u_analytic| over the layers, / u_max
  double centre = 0;  // the mean u of the two middle layers / the analytic value there
  double spread = 0;  // the largest |u_i - mean of its layer| / u_max: a flow without ends
};

// u_x averaged over each lattice layer y = (j + 1/2) s, against the analytic profile.
Profile measure(const Particles& p) {
  const int layers = int(std::lround(kGap / kSpacing));
  std::vector<double> sum(std::size_t(layers), 0), count(std::size_t(layers), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const int j = std::clamp(int(std::floor(double(p.position[i].y) / kSpacing)), 0, layers - 1);
    sum[std::size_t(j)] += double(p.velocity[i].x);
    count[std::size_t(j)] += 1;
  }
  const double u_max = analytic(kGap / 2);
  Profile out;
  for (int j = 0; j < layers; ++j) {
    const double u = sum[std::size_t(j)] / count[std::size_t(j)];
    out.worst = std::max(out.worst, std::abs(u - analytic((j + 0.5) * kSpacing)) / u_max);
  }
  const std::size_t a = std::size_t(layers / 2 - 1), b = a + 1;
  out.centre = (sum[a] / count[a] + sum[b] / count[b]) /
               (analytic((double(a) + 0.5) * kSpacing) + analytic((double(b) + 0.5) * kSpacing));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const int j = std::clamp(int(std::floor(double(p.position[i].y) / kSpacing)), 0, layers - 1);
    const double mean = sum[std::size_t(j)] / count[std::size_t(j)];
    out.spread = std::max(out.spread, std::abs(double(p.velocity[i].x) - mean) / u_max);
  }
  return out;
}

// Steady state: the slowest mode decays as exp(-pi^2 nu t / H^2), 247 /s; by 0.08 s it is gone.
Profile steady_profile(double dt, const std::string& solver) {
  TestWorld t(channel_scene(dt, solver), 2);
  t.run_until(0.08);
  return measure(t.world->particles());
}

TEST(PoiseuilleFlow, ImplicitViscosityAtNuOneGivesTheParabolicProfileInAPeriodicChannel) {
  const double dt = 1e-3;
  const Profile p = steady_profile(dt, "pcisph");
  std::printf(
      "Poiseuille, nu %g m^2/s, dt %g s (%.0f x the explicit limit): largest layer error %.2f %% "
      "of u_max, centre %.4f of analytic, spread within layers %.2g %%\n",
      kNu, dt, dt / kExplicitLimit, 100 * p.worst, p.centre, 100 * p.spread);
  record_validation(
      "plane Poiseuille flow at nu = 1 m^2/s, implicit viscosity at 143 x the explicit step, "
      "periodic in x and z: largest layer error / u_max",
      "g y (H - y) / (2 nu)", "0", "within 3 %", p.worst);
  EXPECT_LT(p.worst, 0.03);
  EXPECT_NEAR(p.centre, 1, 0.03);
  // Periodic images carry the flow across the faces: no layer varies along x or z.
  EXPECT_LT(p.spread, 0.01);
}

// Every fluid solver shares the viscosity and the periodic domain.
TEST(PoiseuilleFlow, EveryFluidSolverReachesTheProfile) {
  for (const char* solver : {"dfsph", "iisph", "wcsph"}) {
    const Profile p = steady_profile(1e-3, solver);
    std::printf("Poiseuille with %s: largest layer error %.2f %% of u_max, centre %.4f\n", solver,
                100 * p.worst, p.centre);
    EXPECT_LT(p.worst, 0.03) << solver;
  }
}

}  // namespace
}  // namespace upf::testing
