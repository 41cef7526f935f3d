// Archimedes' principle with two-way rigid-fluid coupling (Akinci et al. 2012) and Bullet: a
// body lighter than water floats with the weight of water it displaces equal to its own; a
// heavier one sinks to the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "coupling_scenes.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kSpacing = 0.02;  // tank_with_body's
constexpr double kTank = 0.5;      // m, its cube tank
constexpr double kWater = 0.3;     // m, its water's initial depth

// The free surface away from the body: the mean over a grid of columns farther than `clear`
// from the body's centre of the highest liquid particle centre plus half a spacing.
double surface_height(const Particles& p, double cx, double cz, double clear) {
  double sum = 0;
  int columns = 0;
  for (double x = 0.03; x < kTank; x += 0.04)
    for (double z = 0.03; z < kTank; z += 0.04) {
      if (std::max(std::abs(x - cx), std::abs(z - cz)) < clear) continue;
      double top = -1;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.type[i] == ParticleType::Liquid && std::abs(double(p.position[i].x) - x) < 0.02 &&
            std::abs(double(p.position[i].z) - z) < 0.02)
          top = std::max(top, double(p.position[i].y));
      if (top < 0) continue;
      sum += top + 0.5 * kSpacing;
      ++columns;
    }
  return sum / columns;
}

// A cube of density 500 floats half submerged: its weight rho_b L^3 g equals the weight of the
// water it displaces, rho_w V_sub g, so V_sub = L^3 / 2. A cube with rho_b / rho_w = 0.5 is not
// stable upright (its metacentre lies below its centre of mass for 0.21 < s < 0.79), so it tilts;
// but every plane through a cube's centre halves its volume, so in any orientation "half
// submerged" means "centre on the waterline": draft 0.5 L when upright. Bound: 5 % of L.
TEST(Buoyancy, CubeOfHalfWaterDensityFloatsWithItsCentreOnTheWaterline) {
  constexpr double kSide = 0.16;
  // Lowered to just above the water: it falls in, bobs and settles.
  TestWorld t(tank_with_body("pcisph", 500, "unit_box.obj", kSide,
                             {0.25, kWater + 0.5 * kSide + 0.01, 0.25}),
              2);
  t.run_until(2.5);
  double offset = 0, speed = 0;
  int samples = 0;
  while (t.world->time() < 3.0 - 1e-9) {
    t.run_until(t.world->time() + 0.05);
    const BodyState& s = bodies_of(*t.world).state(0);
    const double surface =
        surface_height(t.world->particles(), s.position.x(), s.position.z(), 0.16);
    offset += s.position.y() - surface;
    speed = std::max(speed, s.velocity.norm());
    ++samples;
  }
  offset /= samples;
  std::printf("cube centre - waterline over the last 0.5 s: %.4f m = %.3f L; max speed %.4f m/s\n",
              offset, offset / kSide, speed);
  record_validation("cube (density 500) centre above the waterline, as a share of L",
                    "Archimedes: half submerged", "0", "within 0.05", offset / kSide);
  EXPECT_LT(std::abs(offset), 0.05 * kSide);
  EXPECT_LT(speed, 0.05);
}

// A sphere of density 1500 is heavier than the water it displaces: it sinks and comes to rest
// on the floor (y = 0), where Bullet's contact with the container holds it.
TEST(Buoyancy, SphereOfDensity1500SinksAndRestsOnTheFloor) {
  constexpr double kRadius = 0.06;  // the icosphere asset has radius 0.5
  TestWorld t(tank_with_body("pcisph", 1500, "icosphere.ply", 2 * kRadius, {0.25, 0.2, 0.25}), 2);
  t.run_until(1.5);
  const BodyState& s = bodies_of(*t.world).state(0);
  const double bottom = s.position.y() - kRadius;
  std::printf("sphere bottom %.4f m above the floor, speed %.4f m/s\n", bottom, s.velocity.norm());
  record_validation("sphere (density 1500) bottom above the floor", "Archimedes: sinks, rests",
                    "0 m", "within 0.01 m (half a spacing)", bottom, "m");
  EXPECT_LT(std::abs(bottom), 0.5 * kSpacing);
  EXPECT_LT(s.velocity.norm(), 0.02);
}

// A fixed body under water feels the weight of the water it displaces, rho_w g L^3, upwards:
// a 0.16 m cube of a frozen material (a static body, which nothing moves) held at mid-depth in
// tank_with_body's water, measured over 0.8-1.5 s (PCISPH's defaults). Its fluid force is the
// reactions of the water's boundary forces on its frozen particles (boundary_reactions.h); before
// those existed it read the penetration guard's momentum alone, about 0. Bound 5 %: measured
// 1.040. With the solver's wall_pressure 1 the cube's particles carry the wall pressure, and it
// reads 1.117 (docs/bodies.md), as a floating body did when it carried it (boundary_pressure.h).
TEST(Buoyancy, AFixedCubeUnderWaterIsPushedUpWithTheWeightOfWaterItDisplaces) {
  constexpr double kSide = 0.16;
  nlohmann::json doc = tank_with_body("pcisph", 1000, "unit_box.obj", kSide, {0.25, 0.14, 0.25});
  doc["materials"]["solid"] = {{"type", "frozen"}};
  TestWorld t(doc, 2);
  t.run_until(0.8);
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  double time = 0;
  while (t.world->time() < 1.5 - 1e-9) {
    t.world->step(t.world->next_time_step_until(1.5));
    const double dt = t.world->last_step().dt;
    impulse += dt * bodies_of(*t.world).state(0).fluid_force;
    time += dt;
  }
  const Eigen::Vector3d force = impulse / time;
  const double displaced = 1000 * 9.81 * kSide * kSide * kSide;
  std::printf("fixed cube under water: mean fluid force (%.3f, %.3f, %.3f) N, rho g V %.3f N\n",
              force.x(), force.y(), force.z(), displaced);
  record_validation("mean fluid force on a fixed submerged cube / rho_w g V", "Archimedes", "1",
                    "within 5 %", force.y() / displaced);
  EXPECT_NEAR(force.y(), displaced, 0.05 * displaced);
  EXPECT_LT(std::hypot(force.x(), force.z()), 0.01 * displaced);
}

}  // namespace
}  // namespace upf::testing

// Every fluid solver, plug-ins included, holding up a floating cube: test_every_fluid_solver.cpp.
