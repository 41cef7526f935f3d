// The force of grains on their container's faces (dem_wall_forces.h), what a load cell under a
// silo reads. A random block of 6 mm grains poured into a 6 cm square column settles for 1 s;
// then the faces' forces are averaged over 0.1 s, and checked against:
//
//  - Newton's second law: floor force + the walls' friction along gravity - weight = the rate of
//    change of the grains' vertical momentum over the window, within 0.1 % of the weight (at
//    rest, static equilibrium: the two carry the weight).
//  - Frictionless walls carry none of the weight.
//  - Coulomb: the walls' friction is at most mu_w times their normal force.
//  - Janssen (1895): wall friction carries part of the weight, and a floor under a column four
//    times as high as wide reads less than it. Here 66 %: a poured column mobilises only about
//    13 % of its wall friction (measured: drag / (mu_w N_walls)), so it is far from Janssen's
//    saturation (with friction fully mobilised and K = 0.5, 24 %), which experiments reach by
//    lowering the floor a little after filling (Vanel & Clement 1999).
//
// The grains' contact load (sum of |F| over each grain's contacts, exported as a field) grows
// with depth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

constexpr double kSpacing = 0.006;  // grain diameter, m
constexpr double kWidth = 0.06;     // the column's side, m
constexpr double kHeight = 0.45;    // the random block's height before it settles, m
constexpr double kGravity = 9.81;

struct ColumnForces {
  double weight = 0;         // N, of every grain
  double floor = 0;          // N, y_min's normal force, time-averaged
  double wall_drag = 0;      // N, the walls' friction along gravity (down on the walls)
  double side_normal = 0;    // N, the four side faces' normal forces together
  double top = 0;            // N, y_max's normal force
  double bed_height = 0;     // m, of the settled bed (top grain's surface)
  double momentum_rate = 0;  // N, d/dt of the grains' vertical momentum over the window
  double deep_load = 0;      // N, mean contact load of the grains in the lowest 2 cm
  double shallow_load = 0;   // N, the same within 2 cm of the bed's top
};

ColumnForces settled_column(double wall_friction) {
  const nlohmann::json doc = {
      {"particle_spacing", kSpacing},
      {"materials",
       {{"sand",
         {{"type", "granular"},
          {"density", 2500},
          {"normal_stiffness", 2000},
          {"restitution", 0.3},
          {"friction", 0.5},
          {"wall_friction", wall_friction}}},
        {"walls", {{"type", "frozen"}}}}},
      {"containers",
       {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {kWidth, kHeight + 0.05, kWidth}}}}},
      {"granular_blocks",
       {{{"material", "sand"},
         {"min", {0, 0, 0}},
         {"max", {kWidth, kHeight, kWidth}},
         {"packing", "random"},
         {"solid_fraction", 0.3}}}},
      {"time", {{"dt_max", 0.002}}}};
  TestWorld t(doc, 2);
  World& w = *t.world;
  const Solver& dem = *w.solvers().front();
  const std::vector<SolverTable> tables = dem.tables(w);
  EXPECT_EQ(tables.size(), 1u);
  EXPECT_EQ(tables.at(0).file, "dem_linear_walls");
  t.run_until(1.0);
  ColumnForces c;
  const Particles& p = w.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Granular) c.weight += double(p.mass[i]) * kGravity;
  auto momentum = [&] {
    double py = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Granular) py += double(p.mass[i]) * double(p.velocity[i].y);
    return py;
  };
  const double p0 = momentum();
  double time = 0;
  while (w.time() < 1.1 - 1e-12) {
    w.step(w.next_time_step_until(1.1));
    const double dt = w.last_step().dt;
    const std::vector<double> row = dem.table_rows(w, p).at(0);  // x/y/z min/max, shear x, y, z
    c.floor += row[2] * dt;
    c.top += row[3] * dt;
    c.side_normal += (row[0] + row[1] + row[4] + row[5]) * dt;
    c.wall_drag += -row[7] * dt;
    time += dt;
  }
  c.momentum_rate = (momentum() - p0) / time;
  c.floor /= time;
  c.top /= time;
  c.side_normal /= time;
  c.wall_drag /= time;
  const std::vector<Real>& load = *p.find_scalar("dem.contact_load");
  double top = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Granular) top = std::max(top, double(p.position[i].y));
  c.bed_height = top + 0.5 * kSpacing;
  int deep = 0, shallow = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] != ParticleType::Granular) continue;
    if (p.position[i].y < 0.02) c.deep_load += load[i], ++deep;
    if (p.position[i].y > top - 0.02) c.shallow_load += load[i], ++shallow;
  }
  c.deep_load /= std::max(deep, 1);
  c.shallow_load /= std::max(shallow, 1);
  std::printf(
      "wall friction %.2f: weight %.4f N, floor %.4f N, wall drag %.4f N, side normals %.4f N, "
      "top %.4f N, bed %.4f m, contact load deep %.5f N, near the top %.5f N, dP/dt %.5f N\n",
      wall_friction, c.weight, c.floor, c.wall_drag, c.side_normal, c.top, c.bed_height,
      c.deep_load, c.shallow_load, c.momentum_rate);
  return c;
}

// Newton's second law for the grains over the window, the floor and walls' forces as exported.
void expect_momentum_balance(const ColumnForces& c) {
  EXPECT_NEAR(c.floor + c.wall_drag - c.weight, c.momentum_rate, 1e-3 * c.weight);
  EXPECT_EQ(c.top, 0);
  EXPECT_GT(c.side_normal, 0.05 * c.weight) << "the grains push the side walls outwards";
  EXPECT_GT(c.deep_load, 3 * c.shallow_load) << "the contact load grows with depth";
}

TEST(DemWallForces, FrictionlessWallsLeaveTheWeightOnTheFloor) {
  const ColumnForces c = settled_column(0);
  expect_momentum_balance(c);
  record_validation("(floor force - weight - dP/dt) / weight, frictionless walls",
                    "Newton's second law", "0", "below 0.1 %",
                    (c.floor - c.weight - c.momentum_rate) / c.weight);
  EXPECT_EQ(c.wall_drag, 0);
  // Still creeping down at 1 s (dP/dt = -2 % of the weight), the floor carries nearly all of it.
  EXPECT_GT(c.floor, 0.95 * c.weight);
}

TEST(DemWallForces, WallFrictionCarriesPartOfTheWeight) {
  constexpr double kMuWall = 0.5;
  const ColumnForces c = settled_column(kMuWall);
  expect_momentum_balance(c);
  record_validation("(floor + wall friction) / grain weight, a settled column",
                    "static equilibrium", "1", "within 1 %", (c.floor + c.wall_drag) / c.weight);
  EXPECT_NEAR(c.floor + c.wall_drag, c.weight, 0.01 * c.weight);
  EXPECT_LE(c.wall_drag, kMuWall * c.side_normal) << "Coulomb's limit";
  const double share = c.floor / c.weight;
  std::printf("floor share %.4f, wall friction mobilised %.3f\n", share,
              c.wall_drag / (kMuWall * c.side_normal));
  record_validation("floor force / grain weight, wall friction 0.5, H / D = 4",
                    "Janssen 1895: the walls carry part of the weight", "below 1", "below 0.8",
                    share);
  EXPECT_LT(share, 0.8) << "the walls carry part of the weight";
}

}  // namespace
}  // namespace upf::testing
