// DEM contact models against their analytic answers: the linear spring-dashpot's restitution and
// contact time (Cundall & Strack 1979; the damped oscillator), Hertz's impact of two glass
// spheres (Chung & Ooi 2011, benchmark 1), rolling and sliding down an incline (rigid-body
// mechanics), and energy conservation of elastic, frictionless grains in a closed box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene_helpers.h"
#include "solvers/dem/dem_solver.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One grain of radius r centred at c (a granular block one diameter wide), moving at v.
nlohmann::json grain(const std::string& material, const std::vector<double>& c, double r,
                     const std::vector<double>& v) {
  return {{"material", material},
          {"min", {c[0] - r, c[1] - r, c[2] - r}},
          {"max", {c[0] + r, c[1] + r, c[2] + r}},
          {"velocity", v}};
}

nlohmann::json grain_scene(const nlohmann::json& material, const std::string& solver,
                           const std::vector<double>& gravity, nlohmann::json blocks,
                           double fixed_dt, const std::vector<double>& box_max,
                           double substep_fraction = 0.5) {
  nlohmann::json mat = material;
  mat["type"] = "granular";
  mat["solver"] = {{"name", solver}, {"substep_fraction", substep_fraction}};
  return {{"gravity", gravity},
          {"particle_spacing", 0.02},
          {"materials", {{"sand", mat}, {"walls", {{"type", "frozen"}}}}},
          {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", box_max}}}},
          {"granular_blocks", blocks},
          {"time", {{"fixed_dt", fixed_dt}}}};
}

// The indices of the grains now, in id order (the world reorders particles every few steps).
std::vector<std::size_t> grains(const Particles& p) {
  std::vector<std::size_t> g;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Granular) g.push_back(i);
  std::sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  return g;
}

struct Impact {
  double restitution = 0, contact_time = 0, peak_force = 0;
};

// Steps a two-body impact along x one sub-step at a time: while `touching` holds, the contact
// lasts; the restitution is the ratio of the separation to the approach speed; the peak force
// is m dv/dt of grain 0.
template <class Touching, class Approach>
Impact measure_impact(TestWorld& t, double dt, Touching touching, Approach approach) {
  const Particles& p = t.world->particles();
  const double before = approach();
  Impact out;
  bool started = false;
  for (int step = 0; step < 20000; ++step) {
    const double v0 = double(p.velocity[grains(p)[0]].x);
    t.world->step(dt);
    const std::size_t g0 = grains(p)[0];
    const double dv = double(p.velocity[g0].x) - v0;
    out.peak_force = std::max(out.peak_force, std::abs(double(p.mass[g0]) * dv / dt));
    if (touching()) {
      started = true;
      out.contact_time += dt;
    } else if (started) {
      break;
    }
  }
  out.restitution = -approach() / before;
  return out;
}

// Two grains of radius r meeting head-on along x.
Impact measure_pair_impact(TestWorld& t, double dt, double r) {
  const Particles& p = t.world->particles();
  auto gap = [&] {
    const auto g = grains(p);
    return double(norm(p.position[g[1]] - p.position[g[0]])) - 2 * r;
  };
  auto approach = [&] {
    const auto g = grains(p);
    return double(p.velocity[g[0]].x - p.velocity[g[1]].x);
  };
  return measure_impact(
      t, dt, [&] { return gap() < 0; }, approach);
}

// `what`'s restitution and contact time against the linear model's analytic e and t_c, within
// 2 %, each recorded.
void expect_linear_impact(const char* what, double e, double tc, const Impact& i) {
  char label[96], expected[32];
  std::snprintf(label, sizeof label, "restitution of %s, e = %.1f", what, e);
  std::snprintf(expected, sizeof expected, "%.1f", e);
  record_validation(label, "linear spring-dashpot, analytic", expected, "within 2 %",
                    i.restitution);
  std::snprintf(label, sizeof label, "contact time of %s, e = %.1f", what, e);
  std::snprintf(expected, sizeof expected, "%.4g s", tc);
  record_validation(label, "linear spring-dashpot, analytic", expected, "within 2 %",
                    i.contact_time, "s");
  EXPECT_NEAR(i.restitution, e, 0.02 * e);
  EXPECT_NEAR(i.contact_time, tc, 0.02 * tc);
}

TEST(DemLinear, HeadOnImpactOfTwoSpheresMatchesRestitutionAndContactTime) {
  const double r = 0.01, kn = 1e4, density = 2500;
  const double m = density * 4.0 / 3.0 * kPi * r * r * r, m_eff = m / 2;
  for (double e : {0.3, 0.6, 0.9}) {
    const double zeta = -std::log(e) / std::sqrt(kPi * kPi + std::log(e) * std::log(e));
    const double tc = kPi / (std::sqrt(kn / m_eff) * std::sqrt(1 - zeta * zeta));
    const double dt = tc / 400;
    nlohmann::json mat = {
        {"density", density}, {"normal_stiffness", kn}, {"restitution", e}, {"friction", 0.0}};
    TestWorld t(grain_scene(mat, "dem_linear", {0, 0, 0},
                            {grain("sand", {0.2, 0.05, 0.05}, r, {0.5, 0, 0}),
                             grain("sand", {0.2 + 2 * r + 0.002, 0.05, 0.05}, r, {-0.5, 0, 0})},
                            dt, {0.3, 0.1, 0.1}),
                2);
    const Impact i = measure_pair_impact(t, dt, r);
    std::printf("linear e = %.1f: restitution %.4f, contact time %.4e s (analytic %.4e)\n", e,
                i.restitution, i.contact_time, tc);
    expect_linear_impact("a head-on impact", e, tc, i);
  }
}

TEST(DemLinear, SphereOnAWallMatchesRestitutionAndContactTime) {
  const double r = 0.01, kn = 1e4, density = 2500;
  const double m = density * 4.0 / 3.0 * kPi * r * r * r;  // the wall is rigid: m* = m
  for (double e : {0.3, 0.6, 0.9}) {
    const double zeta = -std::log(e) / std::sqrt(kPi * kPi + std::log(e) * std::log(e));
    const double tc = kPi / (std::sqrt(kn / m) * std::sqrt(1 - zeta * zeta));
    const double dt = tc / 400;
    nlohmann::json mat = {
        {"density", density}, {"normal_stiffness", kn}, {"restitution", e}, {"friction", 0.0}};
    TestWorld t(grain_scene(mat, "dem_linear", {0, 0, 0},
                            nlohmann::json::array(
                                {grain("sand", {r + 0.001, 0.05, 0.05}, r, {-0.5, 0, 0})}),
                            dt, {0.3, 0.1, 0.1}),
                2);
    const Particles& p = t.world->particles();
    const Impact i = measure_impact(
        t, dt, [&] { return double(p.position[grains(p)[0]].x) < r; },
        [&] { return -double(p.velocity[grains(p)[0]].x); });
    std::printf("wall e = %.1f: restitution %.4f, contact time %.4e s (analytic %.4e)\n", e,
                i.restitution, i.contact_time, tc);
    expect_linear_impact("a sphere on a wall", e, tc, i);
  }
}

// Chung & Ooi 2011 ("Benchmark tests for verifying discrete element modelling codes at particle
// impact level", Granular Matter 13), test 1: two glass spheres, R = 0.010 m, E = 4.8e10 Pa,
// nu = 0.20, rho = 2800 kg/m^3, elastic, meeting head-on at 10 m/s each. Hertz theory gives a
// peak force of 10.70 kN and a contact time of 40.3 microseconds.
TEST(DemHertz, ChungOoiBenchmarkOneGlassSpheres) {
  const double r = 0.01;
  nlohmann::json mat = {{"density", 2800},    {"youngs_modulus", 4.8e10}, {"poisson_ratio", 0.2},
                        {"restitution", 1.0}, {"friction", 0.0},          {"radius", r}};
  const double dt = 4.03e-5 / 800;
  TestWorld t(grain_scene(mat, "dem_hertz", {0, 0, 0},
                          {grain("sand", {0.1, 0.05, 0.05}, r, {10, 0, 0}),
                           grain("sand", {0.1 + 2 * r + 1e-5, 0.05, 0.05}, r, {-10, 0, 0})},
                          dt, {0.2, 0.1, 0.1}),
              2);
  const Impact i = measure_pair_impact(t, dt, r);
  std::printf(
      "Hertz glass spheres: peak force %.1f N (10700), contact time %.2f us (40.3), "
      "restitution %.4f\n",
      i.peak_force, i.contact_time * 1e6, i.restitution);
  record_validation("peak force, glass spheres meeting at 10 m/s each",
                    "Chung & Ooi 2011, benchmark 1 (Hertz)", "10.70 kN", "within 3 %",
                    i.peak_force / 1e3, "kN");
  record_validation("contact time, glass spheres meeting at 10 m/s each",
                    "Chung & Ooi 2011, benchmark 1 (Hertz)", "40.3 us", "within 3 %",
                    i.contact_time * 1e6, "us");
  EXPECT_NEAR(i.peak_force, 10.70e3, 0.03 * 10.70e3);
  EXPECT_NEAR(i.contact_time, 40.3e-6, 0.03 * 40.3e-6);
}

// A sphere on an incline (gravity tilted by theta over a flat floor) rolls without slipping,
// a = 5/7 g sin(theta), when tan(theta) <= 7/2 mu, and slides, a = g (sin - mu cos), otherwise.
// `wall_mu` >= 0 sets the material's wall_friction (the floor is a container wall).
double incline_acceleration(double theta_degrees, double mu, double wall_mu = -1) {
  const double th = theta_degrees * kPi / 180, g = 9.81;
  nlohmann::json mat = {
      {"density", 2500}, {"normal_stiffness", 1e5}, {"restitution", 0.3}, {"friction", mu}};
  if (wall_mu >= 0) mat["wall_friction"] = wall_mu;
  const double r = 0.01;
  TestWorld t(grain_scene(mat, "dem_linear", {g * std::sin(th), -g * std::cos(th), 0},
                          nlohmann::json::array({grain("sand", {0.1, r, 0.1}, r, {0, 0, 0})}), 2e-5,
                          {1.5, 0.2, 0.2}),
              2);
  const Particles& p = t.world->particles();
  t.run_until(0.05);  // the normal bounce of the start dies out
  const double v1 = double(p.velocity[grains(p)[0]].x), t1 = t.world->time();
  t.run_until(0.25);
  return (double(p.velocity[grains(p)[0]].x) - v1) / (t.world->time() - t1);
}

// Friction on walls is the material's wall_friction, not its grain-grain friction: with 0.9
// between grains and 0.05 on the floor, a sphere on a 30 degree incline slides,
// a = g (sin - 0.05 cos) = 4.48 m/s^2 (tan 30 = 0.58 > 7/2 0.05); at the grain-grain 0.9 it would
// roll, a = 5/7 g sin = 3.50 m/s^2.
TEST(DemLinear, SphereOnAWallFeelsTheWallFriction) {
  const double a = incline_acceleration(30, 0.9, 0.05);
  const double th = 30 * kPi / 180;
  const double expected = 9.81 * (std::sin(th) - 0.05 * std::cos(th));
  std::printf("wall friction 0.05: a = %.4f m/s^2 (g (sin - mu_w cos) = %.4f)\n", a, expected);
  char text[32];
  std::snprintf(text, sizeof text, "%.4g m/s^2", expected);
  record_validation("sliding acceleration on a wall with wall_friction 0.05, grains 0.9",
                    "Coulomb: g (sin - mu_w cos)", text, "within 2 %", a, "m/s^2");
  EXPECT_NEAR(a, expected, 0.02 * expected);
}

TEST(DemLinear, SphereRollsWithoutSlippingDownAGentleIncline) {
  const double a = incline_acceleration(20, 0.5);  // tan 20 = 0.36 <= 1.75
  const double expected = 5.0 / 7.0 * 9.81 * std::sin(20 * kPi / 180);
  std::printf("rolling: a = %.4f m/s^2 (5/7 g sin theta = %.4f)\n", a, expected);
  char text[32];
  std::snprintf(text, sizeof text, "%.4g m/s^2", expected);
  record_validation("rolling acceleration down a 20 degree incline, mu 0.5",
                    "rigid-body mechanics: 5/7 g sin theta", text, "within 2 %", a, "m/s^2");
  EXPECT_NEAR(a, expected, 0.02 * expected);
}

TEST(DemLinear, SphereSlidesDownASteepIncline) {
  const double th = 30 * kPi / 180, mu = 0.1;  // tan 30 = 0.58 > 0.35
  const double a = incline_acceleration(30, mu);
  const double expected = 9.81 * (std::sin(th) - mu * std::cos(th));
  std::printf("sliding: a = %.4f m/s^2 (g (sin - mu cos) = %.4f)\n", a, expected);
  char text[32];
  std::snprintf(text, sizeof text, "%.4g m/s^2", expected);
  record_validation("sliding acceleration down a 30 degree incline, mu 0.1",
                    "Coulomb: g (sin - mu cos)", text, "within 2 %", a, "m/s^2");
  EXPECT_NEAR(a, expected, 0.02 * expected);
}

// Elastic (e = 1), frictionless grains in a closed box conserve kinetic plus elastic energy
// (linear springs: 1/2 k_n delta^2 per contact); symplectic Euler keeps the drift bounded.
// Two blocks of 27 grains collide head-on and rattle between the walls for 10^4 sub-steps.
TEST(DemLinear, ElasticFrictionlessGrainsConserveEnergyInAClosedBox) {
  const double kn = 1e4;
  nlohmann::json mat = {
      {"density", 2500}, {"normal_stiffness", kn}, {"restitution", 1.0}, {"friction", 0.0}};
  nlohmann::json blocks = {{{"material", "sand"},
                            {"min", {0.02, 0.02, 0.02}},
                            {"max", {0.08, 0.08, 0.08}},
                            {"velocity", {0.5, 0.1, 0}}},
                           {{"material", "sand"},
                            {"min", {0.12, 0.03, 0.03}},
                            {"max", {0.18, 0.09, 0.09}},
                            {"velocity", {-0.5, 0, 0.2}}}};
  TestWorld t(grain_scene(mat, "dem_linear", {0, 0, 0}, blocks, 0.002, {0.2, 0.12, 0.12}, 0.05), 2);
  const Particles& p = t.world->particles();
  const double r = 0.01;
  auto energy = [&] {
    const auto g = grains(p);
    const std::vector<Vec3>& w = *p.find_vector(kAngularVelocityField);
    double e = 0;
    for (std::size_t a = 0; a < g.size(); ++a) {
      const std::size_t i = g[a];
      const double m = double(p.mass[i]);
      e += 0.5 * m * double(squared_norm(p.velocity[i]));
      e += 0.5 * 0.4 * m * r * r * double(squared_norm(w[i]));
      for (std::size_t b = a + 1; b < g.size(); ++b) {
        const double overlap = 2 * r - double(norm(p.position[i] - p.position[g[b]]));
        if (overlap > 0) e += 0.5 * kn * overlap * overlap;
      }
      for (int axis = 0; axis < 3; ++axis) {
        const double box_max = axis == 0 ? 0.2 : 0.12;
        for (double gap : {double(p.position[i][axis]), box_max - double(p.position[i][axis])})
          if (gap < r) e += 0.5 * kn * (r - gap) * (r - gap);
      }
    }
    return e;
  };
  const double e0 = energy();
  long substeps = 0;
  double drift = 0;
  while (substeps < 10000) {
    t.world->step(0.002);
    substeps += t.world->last_step().solver.iterations;
    drift = std::max(drift, std::abs(energy() - e0) / e0);
  }
  std::printf("energy %.6f J at the start, largest drift %.3e over %ld sub-steps\n", e0, drift,
              substeps);
  record_validation("largest drift of kinetic + elastic energy / initial, 10^4 sub-steps",
                    "energy conservation (elastic, frictionless grains)", "0", "below 1 %", drift);
  EXPECT_LT(drift, 0.01);
}

}  // namespace
}  // namespace upf::testing
