// What the device pipeline's parity tests share: a scene stepped on the CPU executor and on the
// device pipeline's OpenMP instantiation, compared bit for bit (particles, every non-scratch
// field, bodies, step statistics), for 1 and 2 threads.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "coupling/bodies/rigid_body_system.h"
#include "device/device_pipelines.h"
#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "tests/physics/coupling_scenes.h"
#include "tests/physics/pour_scenes.h"
#include "tests/physics/scene_helpers.h"

namespace upf::device_test {

inline nlohmann::json small_dam_break() {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  return doc;
}

inline nlohmann::json small_tank() {
  auto doc = testing::load_sample_json("hydrostatic_tank.json");
  doc["particle_spacing"] = 0.04;
  return doc;
}

template <class T>
inline std::size_t bitwise_differences(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
  return n;
}

// Every array and every field of two worlds' particles, in memory order (both reorder on the
// same cadence, so the orders agree too).
inline void expect_identical(const Particles& a, const Particles& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(bitwise_differences(a.position, b.position), 0u) << "positions differ";
  EXPECT_EQ(bitwise_differences(a.velocity, b.velocity), 0u) << "velocities differ";
  ASSERT_EQ(a.scalar_fields().size(), b.scalar_fields().size());
  // Scratch fields (a solver's per-step arrays) are the CPU solvers': the pipeline keeps its own.
  for (const auto& [name, f] : a.scalar_fields()) {
    if (f.scratch) continue;
    EXPECT_EQ(bitwise_differences(f.values, b.scalar_fields().at(name).values), 0u) << name;
  }
  for (const auto& [name, f] : a.vector_fields()) {
    if (f.scratch) continue;
    EXPECT_EQ(bitwise_differences(f.values, b.vector_fields().at(name).values), 0u) << name;
  }
}

// Every body's state, to the bit.
inline void expect_identical_bodies(const World& a, const World& b) {
  ASSERT_EQ(a.body_systems().size(), b.body_systems().size());
  for (std::size_t s = 0; s < a.body_systems().size(); ++s) {
    const auto x = a.body_systems()[s]->body_states();
    const auto y = b.body_systems()[s]->body_states();
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
      SCOPED_TRACE(x[k].name);
      EXPECT_EQ(x[k].state.position, y[k].state.position);
      EXPECT_EQ(x[k].state.orientation.coeffs(), y[k].state.orientation.coeffs());
      EXPECT_EQ(x[k].state.velocity, y[k].state.velocity);
      EXPECT_EQ(x[k].state.angular_velocity, y[k].state.angular_velocity);
      EXPECT_EQ(x[k].state.fluid_force, y[k].state.fluid_force);
      EXPECT_EQ(x[k].state.fluid_torque, y[k].state.fluid_torque);
    }
  }
}

struct Stepped {
  testing::TestWorld tw;
  std::vector<int> iterations;
  std::vector<double> dts;
  std::size_t guarded = 0;  // fluid particles the bodies' penetration guard moved, all steps
};

// `steps` steps towards the scene's frames (World::step_towards), as `upf run` takes them.
inline void step(Stepped& s, int steps) {
  World& w = *s.tw.world;
  const double frame = 1.0 / 30.0;
  for (int k = 0; k < steps; ++k) {
    const double stop = (std::floor(w.time() / frame + 1e-9) + 1) * frame;
    w.step_towards(stop);
    s.iterations.push_back(w.last_step().solver.iterations);
    for (const auto& b : w.body_systems())
      if (const auto* rigid = dynamic_cast<const RigidBodySystem*>(b.get()))
        s.guarded += rigid->guarded_particles();
    s.dts.push_back(w.last_step().dt);
  }
}

inline Stepped start(const nlohmann::json& doc, int threads, const std::string& device) {
  Stepped s{testing::TestWorld(doc, threads), {}, {}};
  s.tw.world->set_device(make_device_pipeline(device, *s.tw.world));
  return s;
}

// Returns the guarded particles of the CPU run at 2 threads.
inline std::size_t expect_parity(const nlohmann::json& doc, int steps) {
  std::size_t guarded = 0;
  for (int threads : {1, 2}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    Stepped cpu = start(doc, threads, "cpu");
    Stepped omp = start(doc, threads, "omp");
    EXPECT_NE(omp.tw.world->device(), nullptr);
    if (omp.tw.world->device() == nullptr) return 0;
    EXPECT_EQ(omp.tw.world->device()->name(), "omp");
    const auto initial = testing::state_by_id(cpu.tw.world->particles());
    step(cpu, steps);
    step(omp, steps);
    expect_identical(cpu.tw.world->particles(), omp.tw.world->particles());
    expect_identical_bodies(*cpu.tw.world, *omp.tw.world);
    EXPECT_EQ(cpu.guarded, omp.guarded);
    guarded = cpu.guarded;
    EXPECT_EQ(cpu.iterations, omp.iterations);
    EXPECT_EQ(cpu.dts, omp.dts);
    EXPECT_EQ(cpu.tw.world->time(), omp.tw.world->time());
    // The run must have moved: a frozen world would pass trivially.
    const Particles& p = cpu.tw.world->particles();
    EXPECT_GT(testing::bitwise_differences(testing::state_by_id(p), initial, true),
              (p.count(ParticleType::Liquid) + p.count(ParticleType::Granular)) / 2);
  }
  return guarded;
}

}  // namespace upf::device_test
