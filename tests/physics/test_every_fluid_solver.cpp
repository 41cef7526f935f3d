// The coupling contract, checked for every registered fluid solver, plug-ins included (the
// registry of the `upf` program: built-ins, then every extension of UPF_EXTENSION_DIRS). A fluid
// solver assembled from the shared pieces (solvers/fluid/fluid_solver_state.h) pushes bodies and
// takes the grains' drag back; one that forgets either fails here.
//
//   floating cube   Archimedes: a cube of density 500 placed half in the water is held up by a
//                   mean fluid force near its weight (Akinci et al. 2012, eq. 11 reactions);
//   third law       without gravity, a cube shot into water: the momentum of fluid + body stays
//                   what it was over 1000 steps; water falling onto a fixed plate loses, beyond
//                   its weight's impulse, what the plate's fluid force reports;
//   grains          without gravity, a bead shot through water: the water takes up the momentum
//                   the bead loses to drag (Di Felice 1994 on the bead, the opposite on the
//                   liquid).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/upf/app_registry.h"
#include "coupling_scenes.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

Registry every_solver_registry() {
  Registry r = coupled_registry();
  app::register_extensions(r);
  return r;
}

std::vector<std::string> fluid_solver_names() {
  std::vector<std::string> names;
  const Registry registry = every_solver_registry();
  for (const SolverInfo& s : registry.solvers())
    if (s.type == ParticleType::Liquid) names.push_back(s.name);
  return names;
}

// The solver's parameters for a scene without gravity: a weakly compressible solver cannot
// derive its speed of sound from a falling column there, so it gets 15 m/s, 30 times the
// fastest flow of these scenes (density varies by (v/c)^2, 0.1 %).
nlohmann::json solver_without_gravity(const std::string& name) {
  nlohmann::json solver = {{"name", name}};
  const Registry registry = every_solver_registry();
  for (const ParamSpec& p : registry.find_solver(name)->params) {
    if (p.name == "sound_speed") solver[p.name] = 15.0;
    if (p.name == "stiffness") solver[p.name] = 15.0 * 15.0;  // c = sqrt(k)
  }
  return solver;
}

// Is a liquid particle within a support radius (0.04 m) of cube_shot_into_water's tank walls?
bool liquid_near_walls(const Particles& p) {
  const double reach = 0.04, size[3] = {1.4, 0.6, 0.6};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    const double x[3] = {double(p.position[i].x), double(p.position[i].y), double(p.position[i].z)};
    for (int a = 0; a < 3; ++a)
      if (x[a] < reach || x[a] > size[a] - reach) return true;
  }
  return false;
}

class EveryFluidSolver : public ::testing::TestWithParam<std::string> {
 protected:
  TestWorld world_of(const nlohmann::json& doc) {
    return TestWorld(doc, 2, every_solver_registry());
  }
  // Steps cube_shot_into_water's `doc` (see FluidAndBodyConserveMomentumOver1000Steps) and
  // checks that fluid + body momentum drifts by less than 1e-3 of what they exchanged.
  void expect_momentum_kept(const nlohmann::json& doc, const std::string& reference,
                            const std::string& with) {
    TestWorld t = world_of(doc);
    const Eigen::Vector3d body0 = bodies_of(*t.world).momentum();
    const Eigen::Vector3d total0 = body0 + momentum_of(t.world->particles(), ParticleType::Liquid);
    double exchanged = 0, drift = 0;
    int steps = 0;
    for (; steps < 1000 && !liquid_near_walls(t.world->particles()); ++steps) {
      t.world->step(0.0004);
      const Eigen::Vector3d body = bodies_of(*t.world).momentum();
      exchanged = std::max(exchanged, (body - body0).norm());
      drift = std::max(
          drift, (body + momentum_of(t.world->particles(), ParticleType::Liquid) - total0).norm());
    }
    std::printf(
        "%s%s: %d steps, momentum exchanged %.6f kg m/s, largest drift of the total %.3e "
        "(%.2e)\n",
        GetParam().c_str(), with.c_str(), steps, exchanged, drift, drift / exchanged);
    EXPECT_GE(steps, 250);
    EXPECT_GT(exchanged, 0.1 * body0.norm());  // the cube did hit the water
    record_validation("drift of fluid + body momentum / momentum exchanged" + with, reference, "0",
                      "below 1e-3", drift / exchanged);
    EXPECT_LT(drift, 1e-3 * exchanged);
  }
};

// Archimedes, as Buoyancy.CubeOfHalfWaterDensity... but with the cube placed half in the water
// (the water inside it carved away): bound 25 %, the bobbing of a cube let go at its waterline.
// A solver that adds no reactions lets it fall (force 0).
TEST_P(EveryFluidSolver, HoldsUpAFloatingCube) {
  constexpr double kSide = 0.16;
  const double weight = 500 * kSide * kSide * kSide * 9.81;
  TestWorld t = world_of(tank_with_body(GetParam(), 500, "unit_box.obj", kSide, {0.25, 0.3, 0.25}));
  t.run_until(0.3);
  double force = 0;
  int n = 0;
  while (t.world->time() < 0.6 - 1e-9) {
    t.world->step(t.world->next_time_step_until(0.6));
    force += bodies_of(*t.world).state(0).fluid_force.y();
    ++n;
  }
  force /= n;
  std::printf("%s: mean fluid force on the cube %.2f N, weight %.2f N\n", GetParam().c_str(), force,
              weight);
  record_validation("mean fluid force on a half-submerged cube (density 500) / its weight",
                    "Archimedes (Akinci et al. 2012 reactions)", "1", "within 25 %",
                    force / weight);
  EXPECT_NEAR(force, weight, 0.25 * weight);
}

// Newton's third law, as RigidCoupling.FluidAndBodyMomentumIsConservedWithoutGravity: the cube
// loses what the water gains. Without viscosity (the shared Laplacian viscosity is not symmetric
// where densities differ); 1000 steps of 0.4 ms, or fewer if liquid comes within a support
// radius of a wall first (the walls' forces are external): PBF's artificial pressure throws
// single particles off the free surface at about 2 m/s without gravity, and they reach the
// walls after about 400 steps. The cube meets the water after about 110 steps, and the exchange
// is over by step 250: at least 250 steps are required.
TEST_P(EveryFluidSolver, FluidAndBodyConserveMomentumOver1000Steps) {
  expect_momentum_kept(cube_shot_into_water(solver_without_gravity(GetParam())),
                       "Newton's third law (Akinci et al. 2012 reactions)", "");
}

// The same with surface tension and adhesion (Akinci et al. 2013): cohesion pairs inside the
// water, adhesion between the water and the cube with its reaction on the cube (eq. 6, put on
// the body as pressure reactions are), so water and cube together still keep their momentum.
TEST_P(EveryFluidSolver, SurfaceTensionAndAdhesionConserveMomentumWithABody) {
  auto doc = cube_shot_into_water(solver_without_gravity(GetParam()));
  doc["materials"]["water"]["surface_tension"] = 0.5;  // N/m: gamma 0.13 at 2 cm
  doc["materials"]["water"]["adhesion"] = {{"solid", 2.0}};
  expect_momentum_kept(doc, "Newton's third law (Akinci et al. 2013 pair forces)",
                       ", with cohesion and adhesion");
}

// The same with implicit viscosity (Weiler et al. 2018) and viscous friction on the cube: the
// solve's forces are taken pair by pair at the solved velocities, with a symmetric coefficient,
// and their reactions on the cube at the same velocities (implicit_viscosity.h), so water and cube
// keep their momentum whatever the solver's residual (a loose tolerance here).
TEST_P(EveryFluidSolver, ImplicitViscosityConservesMomentumWithABody) {
  auto doc = cube_shot_into_water(solver_without_gravity(GetParam()));
  auto& water = doc["materials"]["water"];
  water["viscosity"] = 0.05;  // m^2/s: the explicit step would be 4e-4 s, the run's 4e-4 s
  water["boundary_viscosity"] = 0.05;
  water["implicit_viscosity"] = 1;
  water["viscosity_tolerance"] = 0.01;
  expect_momentum_kept(doc, "Newton's third law (Weiler et al. 2018 pair forces)",
                       ", with implicit viscosity");
}

// Newton's third law on a static body: a block of water falls 7 cm onto a fixed plate (a frozen
// body) and spreads off its edges, with no other boundary, so the water's momentum changes by
// M g t less the impulse of the plate's reported fluid force (the reactions of boundary_reactions.h
// and the penetration guard's stopped momentum). With the wall pressure where the solver has it
// (the plate's particles then push with P_i + P_b and the hydrostatic part, and take both back).
// Without viscosity, as above; 1000 steps of 0.4 ms, or fewer (at least 500) if water comes within
// a support radius of the container far below and around (SPH's, WCSPH's and PBF's splashes reach
// it after 570-650): the water lands at about step 300. Before
// the reactions on frozen bodies, a static body reported the guard's momentum only, and the drift
// was the whole exchange.
TEST_P(EveryFluidSolver, AFixedPlateReportsTheMomentumTheWaterLoses) {
  nlohmann::json solver = {{"name", GetParam()}};
  const Registry registry = every_solver_registry();
  for (const ParamSpec& p : registry.find_solver(GetParam())->params)
    if (p.name == "wall_pressure") solver[p.name] = 1;
  const nlohmann::json doc = {
      {"particle_spacing", 0.02},
      {"materials",
       {{"water", {{"type", "liquid"}, {"viscosity", 0.0}, {"solver", solver}}},
        {"walls", {{"type", "frozen"}}},
        {"plate", {{"type", "frozen"}}}}},
      {"containers",
       {{{"material", "walls"}, {"min", {-0.2, -0.8, -0.2}}, {"max", {0.8, 0.5, 0.8}}}}},
      {"fluid_blocks",
       {{{"material", "water"}, {"min", {0.2, 0.2, 0.2}}, {"max", {0.4, 0.3, 0.4}}}}},
      {"bodies",
       {{{"name", "plate"},
         {"material", "plate"},
         {"mesh",
          {{"file", kTestMeshes + "unit_box.obj"},
           {"scale", {0.36, 0.06, 0.36}},
           {"position", {0.3, 0.1, 0.3}}}}}}},
      {"time", {{"fixed_dt", 0.0004}}},
  };
  TestWorld t = world_of(doc);
  const Particles& p = t.world->particles();
  double mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Liquid) mass += double(p.mass[i]);
  const Eigen::Vector3d water0 = momentum_of(p, ParticleType::Liquid);
  const Eigen::Vector3d gravity(0, -9.81, 0);
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  double drift = 0;
  int steps = 0;
  // Until the water comes within a support radius of the container (its forces are external).
  auto near_walls = [&] {
    const Particles& now = t.world->particles();
    for (std::size_t i = 0; i < now.size(); ++i) {
      if (now.type[i] != ParticleType::Liquid) continue;
      const Vec3 x = now.position[i];
      if (x.x < -0.16 || x.x > 0.76 || x.z < -0.16 || x.z > 0.76 || x.y < -0.76) return true;
    }
    return false;
  };
  for (; steps < 1000 && !near_walls(); ++steps) {
    t.world->step(0.0004);
    impulse += 0.0004 * bodies_of(*t.world).state(0).fluid_force;
    const Eigen::Vector3d expected = water0 + mass * gravity * t.world->time() - impulse;
    drift = std::max(drift,
                     (momentum_of(t.world->particles(), ParticleType::Liquid) - expected).norm());
  }
  std::printf("%s: impulse on the plate %.4f N s (weight x t %.4f), largest drift %.3e (%.2e)\n",
              GetParam().c_str(), impulse.norm(), mass * 9.81 * t.world->time(), drift,
              drift / impulse.norm());
  EXPECT_GE(steps, 500);
  EXPECT_GT(-impulse.y(), 0.2 * mass * 9.81 * t.world->time()) << "the plate held the water up";
  record_validation(
      "drift of the water's momentum from M g t - the fixed plate's impulse / impulse",
      "Newton's third law (Akinci et al. 2012 reactions on a static body)", "0", "below 1e-3",
      drift / impulse.norm());
  EXPECT_LT(drift, 1e-3 * impulse.norm());
}

// As DemFluid.BeadAndWaterConserveMomentumWithoutGravity: the liquid gathers the opposite of the
// grain's fluid force (CouplingArray::LiquidForce), so bead + water keep their momentum.
TEST_P(EveryFluidSolver, TakesUpTheMomentumAGrainLosesToDrag) {
  TestWorld t = world_of(grain_in_water(solver_without_gravity(GetParam()), 2500, 0.008, {0, 0, 0},
                                        {0.3, 0, 0}, true));
  const Eigen::Vector3d grain0 = momentum_of(t.world->particles(), ParticleType::Granular);
  const Eigen::Vector3d total0 = grain0 + momentum_of(t.world->particles(), ParticleType::Liquid);
  t.run_until(0.2);
  const Eigen::Vector3d grain = momentum_of(t.world->particles(), ParticleType::Granular);
  const double lost = (grain0 - grain).norm();
  const double drift =
      (grain + momentum_of(t.world->particles(), ParticleType::Liquid) - total0).norm();
  std::printf("%s: bead lost %.4e kg m/s of %.4e; drift of bead + water %.3e (%.2e)\n",
              GetParam().c_str(), lost, grain0.norm(), drift, drift / lost);
  EXPECT_GT(lost, 0.05 * grain0.norm());
  record_validation("drift of bead + water momentum / momentum the bead lost",
                    "Newton's third law (Di Felice 1994 drag, its opposite on the liquid)", "0",
                    "below 1e-3", drift / lost);
  EXPECT_LT(drift, 1e-3 * lost);
}

// Frame 0 shows the initial state's density (Solver::initialize_fields), not zeros: the SPH sum
// at the initial positions. Over the tank's lattice that is the cubic spline's lattice sum,
// 0.99997 rho0, everywhere a support radius below the surface, and less, never zero, above.
// Filling it must not change the first step: a world whose field is zeroed again steps to the
// same bits.
TEST_P(EveryFluidSolver, FrameZeroShowsTheInitialDensityAndTheFirstStepIgnoresIt) {
  auto doc = load_sample_json("hydrostatic_tank.json");
  // Extents in whole spacings: the walls continue the water's lattice.
  doc["particle_spacing"] = 0.04;
  doc["containers"][0]["max"] = {0.32, 0.6, 0.32};
  doc["fluid_blocks"][0]["max"] = {0.32, 0.48, 0.32};
  doc["materials"]["water"]["solver"] = {{"name", GetParam()}};
  TestWorld filled = world_of(doc), zeroed = world_of(doc);
  Particles& p = filled.world->particles();
  const std::vector<Real>& density = p.scalar_field("density");
  const double surface = 0.48, support = 0.08;
  std::size_t interior = 0;
  double worst = 0;  // kg/m^3: the largest interior |density - 0.99997 rho0|
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Liquid) continue;
    EXPECT_GT(density[i], 500) << "particle " << p.id[i];
    if (double(p.position[i].y) < surface - support) {
      ++interior;
      worst = std::max(worst, std::abs(double(density[i]) - 1000.0 * 0.99997));
      EXPECT_NEAR(density[i], 1000.0 * 0.99997, 0.1) << "particle " << p.id[i];
    }
  }
  record_validation("largest frame-0 |density - 0.99997 rho0|, a support radius down",
                    "cubic spline lattice sum, 0.99997 rho0", "0 kg/m^3", "within 0.1 kg/m^3",
                    worst, "kg/m^3");
  EXPECT_GT(interior, 500u);
  std::vector<Real>& erased = zeroed.world->particles().scalar_field("density");
  std::fill(erased.begin(), erased.end(), Real(0));
  filled.world->step(filled.world->next_time_step());
  zeroed.world->step(zeroed.world->next_time_step());
  EXPECT_EQ(bitwise_differences(state_by_id(filled.world->particles()),
                                state_by_id(zeroed.world->particles())),
            0u);
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryFluidSolver, ::testing::ValuesIn(fluid_solver_names()),
                         [](const ::testing::TestParamInfo<std::string>& solver) {
                           return solver.param;
                         });

}  // namespace
}  // namespace upf::testing
