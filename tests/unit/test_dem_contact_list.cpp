// DEM candidate contacts (solvers/dem/dem_contact_list.h): who holds a pair, the reverse index,
// container faces, and springs that survive a reordering of the particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "solvers/dem/dem_contact_list.h"

namespace upf {
namespace {

constexpr MaterialId kSand = 0;

// Every particle lists every other one: enough for these few.
NeighbourList all_pairs(std::size_t n) {
  NeighbourList list;
  list.offsets.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) list.indices.push_back(std::uint32_t(j));
    list.offsets.push_back(std::uint32_t(list.indices.size()));
  }
  return list;
}

struct Scene {
  Particles particles;
  OwnedParticles owned;
  NeighbourList list;
  std::vector<ContainerBox> boxes;
  std::vector<Real> radius;

  void build(DemContactList& contacts) {
    owned.set_materials(1, {kSand});
    owned.rebuild(particles);
    list = all_pairs(particles.size());
    radius.assign(particles.size(), Real(0.01));
    DemContactList::Sources s;
    s.grains = &list;
    s.boxes = &boxes;
    s.radius = radius.data();
    s.skin = Real(0.002);
    contacts.rebuild(particles, owned, owned.range(), s, CpuExecutor(1));
  }
  // The candidate of particle `holder` (by index) whose key is `key`, or -1.
  static int find(const DemContactList& c, std::size_t holder, std::uint32_t key) {
    for (std::uint32_t k = c.begin(holder); k < c.end(holder); ++k)
      if (c.key(k) == key) return int(k);
    return -1;
  }
};

TEST(DemContactList, TheLowerIdHoldsEachPairAndThePartnerFindsItInReverse) {
  Scene s;
  for (int k = 0; k < 3; ++k)
    s.particles.add(Vec3{Real(0.02) * Real(k), 0, 0}, {}, 1, ParticleType::Granular, kSand);
  DemContactList c;
  s.build(c);
  // Ids 0, 1, 2: pairs (0,1), (0,2), (1,2), each held once.
  EXPECT_EQ(c.size(), 3u);
  EXPECT_EQ(c.end(0) - c.begin(0), 2u);
  EXPECT_EQ(c.end(1) - c.begin(1), 1u);
  EXPECT_EQ(c.end(2) - c.begin(2), 0u);
  // Particle 2 reads both of its pairs back, in its own list's order (0, then 1).
  ASSERT_EQ(c.reverse_end(2) - c.reverse_begin(2), 2u);
  EXPECT_EQ(c.reverse_pair(c.reverse_begin(2)), std::uint32_t(Scene::find(c, 0, 2)));
  EXPECT_EQ(c.reverse_pair(c.reverse_begin(2) + 1), std::uint32_t(Scene::find(c, 1, 2)));
  EXPECT_EQ(c.reverse_end(0) - c.reverse_begin(0), 0u);
}

TEST(DemContactList, ContainerFacesWithinReachAreCandidates) {
  Scene s;
  s.boxes.push_back({Vec3{0, 0, 0}, Vec3{1, 1, 1}, 0});
  // 0.011 from the floor (within radius + skin = 0.012), far from the other faces.
  s.particles.add(Vec3{Real(0.5), Real(0.011), Real(0.5)}, {}, 1, ParticleType::Granular, kSand);
  DemContactList c;
  s.build(c);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c.partner(0), kDemWallPartner | 2u);  // container 0, face 2: y = min
  EXPECT_EQ(c.key(0), dem_wall_key(0, 2));
}

TEST(DemContactList, SpringsFollowTheirPairThroughAReordering) {
  Scene s;
  for (int k = 0; k < 4; ++k)
    s.particles.add(Vec3{Real(0.02) * Real(k), 0, 0}, {}, 1, ParticleType::Granular, kSand);
  DemContactList c;
  s.build(c);
  // Give the pair (id 1, id 3) a spring, and separate (id 0, id 2).
  const Vec3 spring{Real(1e-4), Real(2e-4), Real(-3e-4)};
  c.touch(std::uint32_t(Scene::find(c, 1, 3)), spring, {}, {}, {});
  c.separate(std::uint32_t(Scene::find(c, 0, 2)));
  // Reverse the particles in memory: id 1 now sits at index 2.
  s.particles.permute({3, 2, 1, 0});
  s.build(c);
  ASSERT_EQ(s.particles.id[2], 1u);
  const int k = Scene::find(c, 2, 3);
  ASSERT_GE(k, 0);
  EXPECT_EQ(c.xi(std::uint32_t(k)), spring);
  const int apart = Scene::find(c, 3, 2);  // id 0 at index 3, partner id 2
  ASSERT_GE(apart, 0);
  EXPECT_EQ(c.xi(std::uint32_t(apart)), Vec3{});
}

}  // namespace
}  // namespace upf
