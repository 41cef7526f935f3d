// Grains and Bullet bodies: a grain's contact force on a body's boundary particle is read back
// from the grain's contact history, so the pair is exactly opposite, and the per-body sum drives
// Bullet. Checked against Newton's third law.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupling/bodies/rigid_body_system.h"
#include "scene_helpers.h"
#include "validation_record.h"

namespace upf::testing {
namespace {

const std::string kAssets = std::string(UPF_SOURCE_DIR) + "/assets/meshes/";

// Without gravity, a block of 125 grains thrown at a free cube: the grains' momentum plus the
// cube's stays what it was. While grains touch the cube, velocity Verlet holds half a sub-step's
// impulse (h F / 2) in flight, so the balance is checked once the contacts are over.
TEST(DemBodies, GrainsAndBodyConserveMomentumWithoutGravity) {
  nlohmann::json doc = {
      {"gravity", {0, 0, 0}},
      {"particle_spacing", 0.02},
      {"materials",
       {{"sand",
         {{"type", "granular"},
          {"density", 2500},
          {"normal_stiffness", 2e4},
          {"restitution", 0.5},
          {"friction", 0.4}}},
        {"walls", {{"type", "frozen"}}},
        {"solid", {{"type", "rigid"}, {"density", 500}}}}},
      {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {1.2, 0.4, 0.4}}}}},
      {"granular_blocks",
       {{{"material", "sand"},
         {"min", {0.3, 0.15, 0.15}},
         {"max", {0.4, 0.25, 0.25}},
         {"velocity", {1.0, 0, 0}}}}},
      {"bodies",
       {{{"name", "cube"},
         {"material", "solid"},
         {"mesh",
          {{"file", kAssets + "unit_box.obj"}, {"scale", 0.12}, {"position", {0.6, 0.2, 0.2}}}}}}},
      {"time", {{"fixed_dt", 0.001}}},
  };
  TestWorld t(doc, 2);
  const auto& bodies = dynamic_cast<const RigidBodySystem&>(*t.world->body_systems().front());
  auto grain_momentum = [&] {
    const Particles& p = t.world->particles();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Granular)
        sum += double(p.mass[i]) * Eigen::Vector3d(double(p.velocity[i].x), double(p.velocity[i].y),
                                                   double(p.velocity[i].z));
    return sum;
  };
  const Eigen::Vector3d total0 = grain_momentum() + bodies.momentum();
  for (int step = 0; step < 400; ++step) t.world->step(0.001);
  const Eigen::Vector3d body = bodies.momentum();
  const double exchanged = body.norm();
  const double drift = (grain_momentum() + body - total0).norm();
  std::printf(
      "momentum given to the cube %.5f kg m/s (of %.5f), drift of the total %.3e (%.2e), "
      "cube force now %.3e N\n",
      exchanged, total0.norm(), drift, drift / exchanged, bodies.state(0).fluid_force.norm());
  EXPECT_GT(exchanged, 0.1 * total0.norm());  // the grains did hit the cube
  record_validation("drift of grains + body momentum / momentum exchanged",
                    "Newton's third law (contact pairs exactly opposite)", "0", "below 1e-3",
                    drift / exchanged);
  EXPECT_LT(drift, 1e-3 * exchanged);
}

}  // namespace
}  // namespace upf::testing
