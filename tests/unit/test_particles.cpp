// Particles: structure of arrays, stable ids, named fields, permutation, snapshots
// (particles.h; DESIGN.md "Data").
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "framework/core/state_stream.h"
#include "framework/particles/array_sizes.h"
#include "framework/particles/particles.h"

namespace upf {
namespace {

// A particle whose every built-in value is a distinct function of k (exact in float for the
// sizes used here).
void add_numbered(Particles& p, std::uint32_t k) {
  const Real r = Real(k);
  const ParticleType types[] = {ParticleType::Liquid, ParticleType::Rigid, ParticleType::Granular,
                                ParticleType::Frozen};
  p.add(Vec3{r, 2 * r, 3 * r}, Vec3{-r, r + 1, r / 4}, r + Real(0.5), types[k % 4],
        MaterialId(k % 7), BodyId(k % 5) - 1);
  p.boundary_volume.back() = r / 8;
}

void expect_sizes(const Particles& p, std::size_t n) {
  EXPECT_EQ(p.size(), n);
  EXPECT_EQ(p.position.size(), n);
  EXPECT_EQ(p.velocity.size(), n);
  EXPECT_EQ(p.mass.size(), n);
  EXPECT_EQ(p.type.size(), n);
  EXPECT_EQ(p.material.size(), n);
  EXPECT_EQ(p.id.size(), n);
  EXPECT_EQ(p.body.size(), n);
  EXPECT_EQ(p.boundary_volume.size(), n);
  for (const auto& [name, f] : p.scalar_fields()) EXPECT_EQ(f.values.size(), n) << name;
  for (const auto& [name, f] : p.vector_fields()) EXPECT_EQ(f.values.size(), n) << name;
}

TEST(Particles, AddAppendsToEveryArrayWithSequentialIds) {
  Particles p;
  EXPECT_EQ(p.size(), 0u);
  EXPECT_EQ(p.id_bound(), 0u);
  for (std::uint32_t k = 0; k < 10; ++k) {
    const std::size_t index = p.add(Vec3{Real(k), 0, 0}, Vec3{0, Real(k), 0}, Real(k + 1),
                                    ParticleType::Liquid, MaterialId(3));
    EXPECT_EQ(index, k);
    EXPECT_EQ(p.id[index], k);
  }
  expect_sizes(p, 10);
  EXPECT_EQ(p.id_bound(), 10u);
  EXPECT_EQ(p.position[7], (Vec3{7, 0, 0}));
  EXPECT_EQ(p.velocity[7], (Vec3{0, 7, 0}));
  EXPECT_EQ(p.mass[7], Real(8));
  EXPECT_EQ(p.material[7], MaterialId(3));
  EXPECT_EQ(p.body[7], kNoBody);             // default
  EXPECT_EQ(p.boundary_volume[7], Real(0));  // zero for non-boundary particles
}

TEST(Particles, CountsByType) {
  Particles p;
  for (std::uint32_t k = 0; k < 103; ++k) add_numbered(p, k);
  EXPECT_EQ(p.count(ParticleType::Liquid), 26u);  // k % 4 == 0: 0, 4, ..., 100
  EXPECT_EQ(p.count(ParticleType::Rigid), 26u);
  EXPECT_EQ(p.count(ParticleType::Granular), 26u);
  EXPECT_EQ(p.count(ParticleType::Frozen), 25u);
}

TEST(Particles, IdsSurvivePermutationAndKeepCounting) {
  Particles p;
  for (std::uint32_t k = 0; k < 5; ++k) add_numbered(p, k);
  p.permute({4, 3, 2, 1, 0});
  EXPECT_EQ(p.id, (std::vector<ParticleId>{4, 3, 2, 1, 0}));
  EXPECT_EQ(p.add(Vec3{}, Vec3{}, 1, ParticleType::Liquid, 0), 5u);
  EXPECT_EQ(p.id[5], 5u);  // the next id, not a reused index
  EXPECT_EQ(p.id_bound(), 6u);
}

TEST(Particles, NamedFieldsAreCreatedOnceFilledWithInit) {
  Particles p;
  for (std::uint32_t k = 0; k < 4; ++k) add_numbered(p, k);
  std::vector<Real>& pressure = p.scalar_field("test.pressure", Real(2.5));
  EXPECT_EQ(pressure, std::vector<Real>(4, Real(2.5)));
  pressure[1] = 7;
  // Found afterwards: the same storage, not refilled with a new init.
  EXPECT_EQ(&p.scalar_field("test.pressure", Real(-1)), &pressure);
  EXPECT_EQ(pressure[1], Real(7));
  EXPECT_EQ(pressure[0], Real(2.5));

  std::vector<Vec3>& force = p.vector_field("test.force", Vec3{1, 2, 3});
  EXPECT_EQ(force, std::vector<Vec3>(4, Vec3{1, 2, 3}));
  EXPECT_EQ(&p.vector_field("test.force"), &force);

  ASSERT_NE(p.find_scalar("test.pressure"), nullptr);
  EXPECT_EQ(p.find_scalar("test.pressure"), &pressure);
  EXPECT_EQ(p.find_vector("test.force"), &force);
  EXPECT_EQ(p.find_scalar("test.force"), nullptr);  // scalar and vector names are separate
  EXPECT_EQ(p.find_vector("test.pressure"), nullptr);
  EXPECT_EQ(p.find_scalar("missing"), nullptr);
  EXPECT_EQ(p.find_vector("missing"), nullptr);
}

TEST(Particles, NamedFieldsGrowWithAdd) {
  Particles p;
  for (std::uint32_t k = 0; k < 3; ++k) add_numbered(p, k);
  p.scalar_field("test.a", Real(4))[2] = 9;
  p.vector_field("test.v", Vec3{1, 1, 1})[0] = Vec3{5, 6, 7};
  for (std::uint32_t k = 3; k < 50; ++k) add_numbered(p, k);
  expect_sizes(p, 50);
  const std::vector<Real>& a = *p.find_scalar("test.a");
  const std::vector<Vec3>& v = *p.find_vector("test.v");
  // Old values kept; new particles get zero (add() value-initialises named fields).
  EXPECT_EQ(a[0], Real(4));
  EXPECT_EQ(a[2], Real(9));
  EXPECT_EQ(v[0], (Vec3{5, 6, 7}));
  EXPECT_EQ(v[1], (Vec3{1, 1, 1}));
  for (std::size_t i = 3; i < 50; ++i) {
    EXPECT_EQ(a[i], Real(0)) << i;
    EXPECT_EQ(v[i], Vec3{}) << i;
  }
}

TEST(Particles, ExportedFlagIsStickyOnceRequested) {
  Particles p;
  add_numbered(p, 0);
  p.scalar_field("test.a");
  EXPECT_FALSE(p.scalar_fields().at("test.a").exported);
  p.scalar_field("test.a", 0, true);
  EXPECT_TRUE(p.scalar_fields().at("test.a").exported);
  p.scalar_field("test.a", 0, false);  // a later plain request does not un-export
  EXPECT_TRUE(p.scalar_fields().at("test.a").exported);
  p.vector_field("test.v", Vec3{}, true);
  EXPECT_TRUE(p.vector_fields().at("test.v").exported);
}

// permute(order): new[i] = old[order[i]] for every array, built-in and named.
TEST(Particles, PermuteReordersEveryArrayIncludingNamedFields) {
  constexpr std::uint32_t n = 1000;
  Particles p;
  for (std::uint32_t k = 0; k < n; ++k) add_numbered(p, k);
  std::vector<Real>& s1 = p.scalar_field("test.s1");
  std::vector<Real>& s2 = p.scalar_field("test.s2", 0, true);
  std::vector<Vec3>& v1 = p.vector_field("test.v1");
  for (std::uint32_t k = 0; k < n; ++k) {
    s1[k] = Real(k) + Real(0.25);
    s2[k] = -Real(k);
    v1[k] = Vec3{Real(k), -Real(k), Real(k) * 2};
  }
  const Particles old = p;
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(11));
  p.permute(order);
  expect_sizes(p, n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t o = order[i];
    ASSERT_EQ(p.position[i], old.position[o]) << i;
    ASSERT_EQ(p.velocity[i], old.velocity[o]) << i;
    ASSERT_EQ(p.mass[i], old.mass[o]) << i;
    ASSERT_EQ(p.type[i], old.type[o]) << i;
    ASSERT_EQ(p.material[i], old.material[o]) << i;
    ASSERT_EQ(p.id[i], old.id[o]) << i;
    ASSERT_EQ(p.body[i], old.body[o]) << i;
    ASSERT_EQ(p.boundary_volume[i], old.boundary_volume[o]) << i;
    ASSERT_EQ((*p.find_scalar("test.s1"))[i], (*old.find_scalar("test.s1"))[o]) << i;
    ASSERT_EQ((*p.find_scalar("test.s2"))[i], (*old.find_scalar("test.s2"))[o]) << i;
    ASSERT_EQ((*p.find_vector("test.v1"))[i], (*old.find_vector("test.v1"))[o]) << i;
  }
  EXPECT_TRUE(p.scalar_fields().at("test.s2").exported);  // flags untouched

  // The inverse permutation restores the original exactly.
  std::vector<std::uint32_t> inverse(n);
  for (std::uint32_t i = 0; i < n; ++i) inverse[order[i]] = i;
  p.permute(inverse);
  EXPECT_EQ(p.position, old.position);
  EXPECT_EQ(p.velocity, old.velocity);
  EXPECT_EQ(p.mass, old.mass);
  EXPECT_EQ(p.type, old.type);
  EXPECT_EQ(p.material, old.material);
  EXPECT_EQ(p.id, old.id);
  EXPECT_EQ(p.body, old.body);
  EXPECT_EQ(p.boundary_volume, old.boundary_volume);
  EXPECT_EQ(*p.find_scalar("test.s1"), *old.find_scalar("test.s1"));
  EXPECT_EQ(*p.find_scalar("test.s2"), *old.find_scalar("test.s2"));
  EXPECT_EQ(*p.find_vector("test.v1"), *old.find_vector("test.v1"));
}

// snapshot_into copies the built-in arrays and the exported fields, and only those.
TEST(Particles, SnapshotCopiesBuiltInsAndExportedFieldsOnly) {
  Particles p;
  for (std::uint32_t k = 0; k < 20; ++k) add_numbered(p, k);
  std::vector<Real>& exported = p.scalar_field("test.exported", Real(1), true);
  p.scalar_field("test.internal", Real(2));
  std::vector<Vec3>& exported_v = p.vector_field("test.exported_v", Vec3{3, 3, 3}, true);
  p.vector_field("test.internal_v", Vec3{4, 4, 4});
  exported[5] = 55;
  exported_v[6] = Vec3{6, 6, 6};

  Particles snap;
  p.snapshot_into(snap);
  expect_sizes(snap, 20);
  EXPECT_EQ(snap.position, p.position);
  EXPECT_EQ(snap.velocity, p.velocity);
  EXPECT_EQ(snap.mass, p.mass);
  EXPECT_EQ(snap.type, p.type);
  EXPECT_EQ(snap.material, p.material);
  EXPECT_EQ(snap.id, p.id);
  EXPECT_EQ(snap.body, p.body);
  EXPECT_EQ(snap.boundary_volume, p.boundary_volume);
  ASSERT_NE(snap.find_scalar("test.exported"), nullptr);
  EXPECT_EQ(*snap.find_scalar("test.exported"), exported);
  EXPECT_TRUE(snap.scalar_fields().at("test.exported").exported);
  ASSERT_NE(snap.find_vector("test.exported_v"), nullptr);
  EXPECT_EQ(*snap.find_vector("test.exported_v"), exported_v);
  EXPECT_EQ(snap.find_scalar("test.internal"), nullptr);
  EXPECT_EQ(snap.find_vector("test.internal_v"), nullptr);
  EXPECT_EQ(snap.scalar_fields().size(), 1u);
  EXPECT_EQ(snap.vector_fields().size(), 1u);
  // The snapshot carries the id counter: a particle added to it gets the next id.
  EXPECT_EQ(snap.id_bound(), p.id_bound());
}

// Reusing the same snapshot target (as a world keeps its last good state) follows the source:
// sizes, values and fields exported since.
TEST(Particles, SnapshotIntoTheSameTargetFollowsTheSource) {
  Particles p;
  for (std::uint32_t k = 0; k < 10; ++k) add_numbered(p, k);
  p.scalar_field("test.exported", Real(1), true);
  Particles snap;
  p.snapshot_into(snap);

  for (std::uint32_t k = 10; k < 25; ++k) add_numbered(p, k);
  p.position[3] = Vec3{-1, -2, -3};
  p.scalar_field("test.exported")[24] = 42;
  p.scalar_field("test.later", Real(8), true);  // exported after the first snapshot
  std::vector<std::uint32_t> order(25);
  std::iota(order.rbegin(), order.rend(), 0u);
  p.permute(order);

  p.snapshot_into(snap);
  expect_sizes(snap, 25);
  EXPECT_EQ(snap.position, p.position);
  EXPECT_EQ(snap.id, p.id);
  EXPECT_EQ(*snap.find_scalar("test.exported"), *p.find_scalar("test.exported"));
  EXPECT_EQ((*snap.find_scalar("test.exported"))[0], Real(42));  // id 24 is now first
  ASSERT_NE(snap.find_scalar("test.later"), nullptr);
  EXPECT_EQ(*snap.find_scalar("test.later"), std::vector<Real>(25, Real(8)));
  EXPECT_EQ(snap.id_bound(), 25u);
}

}  // namespace
}  // namespace upf

namespace upf {
namespace {

TEST(Particles, RemoveKeepsOrderIdsAndNamedFieldsOfTheRest) {
  Particles p;
  std::vector<Real>& s = p.scalar_field("test.s");
  for (int k = 0; k < 10; ++k) {
    p.add(Vec3{Real(k), 0, 0}, {}, Real(1), k % 2 ? ParticleType::Liquid : ParticleType::Frozen, 0);
    s[std::size_t(k)] = Real(10 * k);
  }
  std::vector<std::uint8_t> doomed(10, 0);
  doomed[0] = doomed[3] = doomed[9] = 1;
  EXPECT_EQ(p.remove(doomed), 3u);
  ASSERT_EQ(p.size(), 7u);
  const std::vector<ParticleId> ids = {1, 2, 4, 5, 6, 7, 8};
  for (std::size_t i = 0; i < ids.size(); ++i) {
    EXPECT_EQ(p.id[i], ids[i]);
    EXPECT_EQ(p.position[i].x, Real(ids[i]));
    EXPECT_EQ((*p.find_scalar("test.s"))[i], Real(10 * ids[i]));
  }
  EXPECT_EQ(p.body.size(), 7u);
  EXPECT_EQ(p.boundary_volume.size(), 7u);
  // New particles keep counting ids from where they were.
  EXPECT_EQ(p.id[p.add({}, {}, Real(1), ParticleType::Liquid, 0)], 10u);
}

TEST(Particles, CheckArraySizesNamesTheCallerAndTheShortArray) {
  Particles p;
  p.scalar_field("test.s");
  for (std::uint32_t k = 0; k < 4; ++k) add_numbered(p, k);
  EXPECT_NO_THROW(check_array_sizes(p, "writer"));

  Particles short_builtin = p;
  short_builtin.material.pop_back();
  try {
    check_array_sizes(short_builtin, "write_vtp");
    FAIL() << "a short built-in array passed";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "write_vtp: particle array 'material' has 3 values for 4 particles");
  }

  Particles short_field = p;
  short_field.scalar_field("test.s").resize(6);
  EXPECT_THROW(check_array_sizes(short_field, "w"), std::logic_error);
}

// How particles travel between MPI ranks (framework/mpi/): pack the listed ones, append them to
// a Particles with the same fields, or overwrite ghosts with fresher copies.
TEST(Particles, PackedParticlesArriveWithEveryArrayAndField) {
  Particles from, to;
  for (auto* p : {&from, &to}) {
    p->scalar_field("s");
    p->vector_field("v");
  }
  for (std::uint32_t k = 0; k < 6; ++k) add_numbered(from, k);
  for (std::size_t i = 0; i < 6; ++i) {
    from.scalar_field("s")[i] = Real(10 + i);
    from.vector_field("v")[i] = Vec3{Real(i), 0, -Real(i)};
  }
  add_numbered(to, 100);
  const std::uint32_t listed[] = {4, 1, 5};
  std::vector<std::uint8_t> bytes;
  from.pack(listed, 3, bytes);
  EXPECT_EQ(bytes.size(), 3 * from.packed_size());
  to.append_packed(bytes.data(), 3);
  expect_sizes(to, 4);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint32_t i = listed[k];
    EXPECT_EQ(to.id[1 + k], from.id[i]);
    EXPECT_EQ(to.position[1 + k], from.position[i]);
    EXPECT_EQ(to.velocity[1 + k], from.velocity[i]);
    EXPECT_EQ(to.type[1 + k], from.type[i]);
    EXPECT_EQ(to.body[1 + k], from.body[i]);
    EXPECT_EQ(to.boundary_volume[1 + k], from.boundary_volume[i]);
    EXPECT_EQ(to.scalar_field("s")[1 + k], from.scalar_field("s")[i]);
    EXPECT_EQ(to.vector_field("v")[1 + k], from.vector_field("v")[i]);
  }
  // A refresh: the owner's values change, and the copies follow.
  from.position[1] = Vec3{9, 9, 9};
  from.scalar_field("s")[5] = 99;
  bytes.clear();
  from.pack(listed, 3, bytes);
  to.set_ghost_count(3);
  to.overwrite_packed(to.owned_size(), bytes.data(), 3);
  EXPECT_EQ(to.position[2], (Vec3{9, 9, 9}));
  EXPECT_EQ(to.scalar_field("s")[3], 99);
  to.truncate(to.owned_size());
  expect_sizes(to, 1);
  EXPECT_EQ(to.ghost_count(), 0u);
  EXPECT_EQ(to.id[0], 0u);
}

// Scratch fields travel with ghosts but not into checkpoints, and come back zeroed at the
// restored length.
TEST(Particles, ScratchFieldsAreLeftOutOfCheckpoints) {
  Particles p;
  const auto kept = p.declare_scalar("kept");
  const auto scratch = p.declare_scratch_scalar("scratch");
  for (std::uint32_t k = 0; k < 3; ++k) add_numbered(p, k);
  p[kept][1] = 5;
  p[scratch][1] = 7;
  StateWriter out;
  p.save_state(out);
  Particles q;
  const auto q_kept = q.declare_scalar("kept");
  const auto q_scratch = q.declare_scratch_scalar("scratch");
  for (std::uint32_t k = 0; k < 3; ++k) add_numbered(q, k);
  q[q_scratch].assign(1, 3);  // a length the restore must fix
  StateReader in(out.bytes(), "test");
  q.restore_state(in);
  EXPECT_EQ(q[q_kept][1], 5);
  EXPECT_EQ(q[q_scratch], std::vector<Real>(3, 0));
  EXPECT_TRUE(p.scalar_fields().at("scratch").scratch);
  EXPECT_FALSE(p.scalar_fields().at("kept").scratch);
}

}  // namespace
}  // namespace upf
