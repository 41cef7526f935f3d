// The device pipeline's grid (device/device_grid.h) on Thrust's OpenMP system against
// NeighbourGrid: the same CSR lists to the last index, on clouds whose memory order is shuffled,
// with several type masks, two lists from one scan, and 1 and 2 threads. Reference: the CPU grid
// (itself checked against brute force in tests/unit/test_neighbour_grid.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "device/device_backend_omp.h"
#include "device/device_grid.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/neighbours/neighbour_grid.h"

namespace upf {
namespace {

using Backend = device::OmpBackend;
template <class T>
using DeviceVector = Backend::vector<T>;

// A block of liquid on a lattice with jitter, frozen walls below it, a few grains and far-away
// stragglers (a cloud whose bounding box is mostly empty), in shuffled memory order.
Particles cloud(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> jitter(Real(-0.004), Real(0.004));
  Particles p;
  const Real s = Real(0.02);
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 15; ++k)
        p.add({Real(i) * s + jitter(rng), Real(0.05) + Real(j) * s + jitter(rng),
               Real(k) * s + jitter(rng)},
              {}, 1, ParticleType::Liquid, 0);
  for (int i = -2; i < 32; ++i)
    for (int k = -2; k < 17; ++k)
      for (int l = 0; l < 2; ++l)
        // A corner of the wall is a static body's (the reactions' body-only queries).
        p.add({Real(i) * s, Real(0.03) - Real(l) * s, Real(k) * s}, {}, 1, ParticleType::Frozen, 1,
              i < 6 && k < 6 ? BodyId(0) : kNoBody);
  for (int g = 0; g < 200; ++g)
    p.add({Real(0.3) + jitter(rng) * 20, Real(0.5) + jitter(rng) * 20, Real(0.1) + jitter(rng)}, {},
          1, ParticleType::Granular, 2);
  p.add({Real(40), Real(-3), Real(7)}, {}, 1, ParticleType::Liquid, 0);
  p.add({Real(40.01), Real(-3), Real(7)}, {}, 1, ParticleType::Liquid, 0);
  std::vector<std::uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), rng);
  p.permute(order);
  return p;
}

template <class T>
std::vector<T> to_host(const DeviceVector<T>& v) {
  return std::vector<T>(v.begin(), v.end());
}

struct DeviceCloud {
  DeviceVector<Vec3> x;
  DeviceVector<std::uint32_t> id;
  DeviceVector<ParticleType> type;
  DeviceVector<BodyId> body;
  explicit DeviceCloud(const Particles& p)
      : x(p.position.begin(), p.position.end()),
        id(p.id.begin(), p.id.end()),
        type(p.type.begin(), p.type.end()),
        body(p.body.begin(), p.body.end()) {}
};

void expect_same_lists(const Particles& p, TypeMask query, std::vector<TypeMask> targets,
                       Real radius, int threads) {
  const CpuExecutor exec(threads);
  NeighbourGrid grid(Real(0.05));
  grid.build(p, exec);
  std::vector<NeighbourList> cpu(targets.size());
  std::vector<NeighbourList*> cpu_outs;
  for (auto& l : cpu) cpu_outs.push_back(&l);
  grid.find_neighbours(p, query, targets, radius, exec, cpu_outs);

  const Backend::ThreadScope scope(threads);
  DeviceCloud d(p);
  device::DeviceGrid<Backend> dgrid(Real(0.05));
  dgrid.build(device::raw<Vec3>(d.x), device::raw<std::uint32_t>(d.id),
              device::raw<ParticleType>(d.type), p.size());
  EXPECT_EQ(to_host(dgrid.sorted_order()), grid.sorted_order());
  EXPECT_EQ(dgrid.cell_count(), grid.cell_count());
  std::vector<device::DeviceNeighbourList<Backend>> dev(targets.size());
  std::vector<device::DeviceNeighbourList<Backend>*> dev_outs;
  for (auto& l : dev) dev_outs.push_back(&l);
  dgrid.find_neighbours(device::raw<ParticleType>(d.type), device::raw<BodyId>(d.body), query,
                        targets.data(), int(targets.size()), radius, dev_outs.data());
  std::size_t total = 0;
  for (std::size_t l = 0; l < targets.size(); ++l) {
    SCOPED_TRACE("list " + std::to_string(l));
    EXPECT_EQ(to_host(dev[l].offsets), cpu[l].offsets);
    EXPECT_EQ(to_host(dev[l].indices), cpu[l].indices);
    total += cpu[l].total();
  }
  if (p.size() > 10) {
    EXPECT_GT(total, 1000u);  // the lists are not trivially empty
  }
}

TEST(DeviceGrid, ListsEqualTheCpuGridsForAnyThreadCount) {
  const Particles p = cloud(7);
  for (int threads : {1, 2}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    expect_same_lists(p, kLiquidMask, {kLiquidMask, kBoundaryMask}, Real(0.05), threads);
    expect_same_lists(p, kAllTypes, {kAllTypes}, Real(0.05), threads);
    expect_same_lists(p, mask_of(ParticleType::Granular),
                      {mask_of(ParticleType::Granular), kLiquidMask}, Real(0.031), threads);
    expect_same_lists(p, kBoundaryMask | kOfBodiesOnly, {kLiquidMask}, Real(0.05), threads);
  }
}

TEST(DeviceGrid, ListsEqualTheCpuGridsOnOtherShuffles) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_lists(cloud(seed), kLiquidMask, {kLiquidMask, kBoundaryMask}, Real(0.05), 2);
  }
}

TEST(DeviceGrid, EmptyAndSingleParticleWorlds) {
  Particles p;
  expect_same_lists(p, kAllTypes, {kAllTypes}, Real(0.05), 1);
  p.add({1, 2, 3}, {}, 1, ParticleType::Liquid, 0);
  expect_same_lists(p, kAllTypes, {kAllTypes}, Real(0.05), 2);
}

}  // namespace
}  // namespace upf
