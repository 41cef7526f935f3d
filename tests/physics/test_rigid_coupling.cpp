// Two-way rigid-fluid coupling (Akinci et al. 2012) with Bullet bodies, checked against Newton's
// third law.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupling_scenes.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

// Newton's third law: without gravity, in a closed tank, a cube pushed into a block of water
// changes the water's momentum by exactly what it loses itself (Akinci's reactions, eq. 11, are
// the fluid forces' opposites, summed per body). Without viscosity: the shared Laplacian
// viscosity weighs pairs by m_j / rho_j, which is not symmetric where densities differ, and
// alone drifts the momentum by 2 % of the exchange here. 1000 steps of 0.4 ms: 0.4 s, before
// the splash reaches the tank's walls (at about 0.45 s), whose forces are external.
TEST(RigidCoupling, FluidAndBodyMomentumIsConservedWithoutGravity) {
  TestWorld t(cube_shot_into_water("pcisph"), 2);
  auto fluid_momentum = [&] { return momentum_of(t.world->particles(), ParticleType::Liquid); };

  const Eigen::Vector3d body0 = bodies_of(*t.world).momentum();
  const Eigen::Vector3d total0 = body0 + fluid_momentum();
  double exchanged = 0, drift = 0;
  for (int step = 0; step < 1000; ++step) {
    t.world->step(0.0004);
    const Eigen::Vector3d body = bodies_of(*t.world).momentum();
    exchanged = std::max(exchanged, (body - body0).norm());
    drift = std::max(drift, (body + fluid_momentum() - total0).norm());
  }
  std::printf("momentum exchanged %.6f kg m/s, largest drift of the total %.3e kg m/s (%.2e)\n",
              exchanged, drift, drift / exchanged);
  record_validation("drift of fluid + body momentum / momentum exchanged",
                    "Newton's third law (Akinci et al. 2012 reactions)", "0", "below 1e-3",
                    drift / exchanged);
  EXPECT_GT(exchanged, 0.1 * body0.norm());  // the cube did hit the water
  EXPECT_LT(drift, 1e-3 * exchanged);
}

}  // namespace
}  // namespace upf::testing
