// The device pipeline's CUDA instantiation against the CPU executor, where a GPU is present
// (scripts/gpu-check runs these; without a GPU or without nvcc they skip and say why).
//   default build (fused multiply-adds): the same particle counts, the density error within the
//     same bound, the surge front at t = 0.3 s within 1 % of the CPU's;
//   with UPF_CUDA_BITWISE=1 (a --fmad=false build, as scripts/gpu-check makes): bitwise equal.
// Reference: the CPU path, itself validated by tests/physics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "../physics/scene_helpers.h"
#include "device/device_pipelines.h"
#include "framework/core/errors.h"

namespace upf {
namespace {

struct Outcome {
  std::size_t liquid = 0;
  double max_avg_density_error = 0;
  double surge_front = 0;  // largest x of a liquid particle [m]
  Particles particles;
};

// The dam break at 4 cm to t = 0.3 s on `device`; skips the test when the device cannot run.
Outcome run(const std::string& device) {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.04;
  testing::TestWorld tw(doc, 2);
  World& w = *tw.world;
  w.set_device(make_device_pipeline(device, w));
  Outcome o;
  while (w.time() < 0.3 - 1e-12) {
    w.step_towards(std::min(0.3, (std::floor(w.time() * 30 + 1e-9) + 1) / 30));
    o.max_avg_density_error =
        std::max(o.max_avg_density_error, w.last_step().solver.avg_density_error);
  }
  o.particles = w.particles();
  for (std::size_t i = 0; i < o.particles.size(); ++i)
    if (o.particles.type[i] == ParticleType::Liquid) {
      ++o.liquid;
      o.surge_front = std::max(o.surge_front, double(o.particles.position[i].x));
    }
  return o;
}

TEST(DevicePipelineCuda, DamBreakAgreesWithTheCpuPath) {
  Outcome gpu;
  try {
    gpu = run("cuda");
  } catch (const InputError& e) {
    GTEST_SKIP() << "no CUDA run here: " << e.what();
  }
  const Outcome cpu = run("cpu");
  EXPECT_EQ(gpu.liquid, cpu.liquid);
  EXPECT_LE(gpu.max_avg_density_error, 0.0105);  // eta = 1 %, as the CPU run
  EXPECT_LE(cpu.max_avg_density_error, 0.0105);
  EXPECT_NEAR(gpu.surge_front, cpu.surge_front, 0.01 * cpu.surge_front);
  if (const char* bitwise = std::getenv("UPF_CUDA_BITWISE");
      bitwise && std::string(bitwise) == "1") {
    ASSERT_EQ(gpu.particles.size(), cpu.particles.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < cpu.particles.size(); ++i)
      differing +=
          std::memcmp(&gpu.particles.position[i], &cpu.particles.position[i], sizeof(Vec3)) != 0;
    EXPECT_EQ(differing, 0u) << "positions that differ in some bit (a --fmad=false build)";
  }
}

}  // namespace
}  // namespace upf
