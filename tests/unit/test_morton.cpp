// Morton (Z-order) keys (G. M. Morton 1966, "A computer oriented geodetic data base and a new
// technique in file sequencing", IBM): bit k of the coordinate on axis a (x = 0, y = 1, z = 2)
// becomes bit 3k + a of the key. Tested against a bit-by-bit implementation of that definition.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "framework/neighbours/morton.h"

namespace upf {
namespace {

// The definition, one bit at a time.
std::uint64_t reference_spread(std::uint32_t v) {
  std::uint64_t out = 0;
  for (std::uint32_t k = 0; k < kMortonAxisBits; ++k)
    if ((v >> k) & 1u) out |= std::uint64_t(1) << (3 * k);
  return out;
}

std::uint64_t reference_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return reference_spread(x) | (reference_spread(y) << 1) | (reference_spread(z) << 2);
}

TEST(Morton, AxisRangeIs21Bits) {
  // 3 x 21 = 63 bits: a key fits a uint64 with the sign bit free.
  EXPECT_EQ(kMortonAxisBits, 21u);
  EXPECT_EQ(kMortonAxisMax, (1u << 21) - 1);
  EXPECT_EQ(morton_key(kMortonAxisMax, kMortonAxisMax, kMortonAxisMax),
            (std::uint64_t(1) << 63) - 1);
}

TEST(Morton, SpreadMovesBitKToBit3K) {
  for (std::uint32_t k = 0; k < kMortonAxisBits; ++k)
    EXPECT_EQ(spread_bits_3d(1u << k), std::uint64_t(1) << (3 * k)) << "bit " << k;
  std::mt19937 rng(1);
  std::uniform_int_distribution<std::uint32_t> value(0, kMortonAxisMax);
  for (int n = 0; n < 10000; ++n) {
    const std::uint32_t v = value(rng);
    ASSERT_EQ(spread_bits_3d(v), reference_spread(v)) << v;
  }
  // Bits above the 21st are ignored (documented range: 21 bits per axis).
  EXPECT_EQ(spread_bits_3d(0xffffffffu), reference_spread(kMortonAxisMax));
}

// Exhaustive: compact_bits_3d is the inverse of spread_bits_3d on every 21-bit value.
TEST(Morton, CompactInvertsSpreadForEvery21BitValue) {
  std::uint32_t failures = 0, first = 0;
  for (std::uint32_t v = 0; v <= kMortonAxisMax; ++v)
    if (compact_bits_3d(spread_bits_3d(v)) != v && failures++ == 0) first = v;
  EXPECT_EQ(failures, 0u) << "first failure at " << first;
}

TEST(Morton, KeyInterleavesAxesAndEachAxisCompactsBack) {
  std::mt19937 rng(2);
  std::uniform_int_distribution<std::uint32_t> value(0, kMortonAxisMax);
  for (int n = 0; n < 20000; ++n) {
    const std::uint32_t x = value(rng), y = value(rng), z = value(rng);
    const std::uint64_t key = morton_key(x, y, z);
    ASSERT_EQ(key, reference_key(x, y, z)) << x << " " << y << " " << z;
    // compact_bits_3d(key >> a) keeps only axis a's bits (as the grid decodes a cell's key).
    ASSERT_EQ(compact_bits_3d(key), x);
    ASSERT_EQ(compact_bits_3d(key >> 1), y);
    ASSERT_EQ(compact_bits_3d(key >> 2), z);
  }
  EXPECT_EQ(morton_key(1, 0, 0), 1u);
  EXPECT_EQ(morton_key(0, 1, 0), 2u);
  EXPECT_EQ(morton_key(0, 0, 1), 4u);
  EXPECT_EQ(morton_key(2, 0, 0), 8u);
  EXPECT_EQ(morton_key(3, 5, 6), reference_key(3, 5, 6));
}

// Z-order is monotone along each axis with the others fixed: the key is the disjoint union of
// the spread coordinates, and spreading preserves order. So key(c + e_a) > key(c).
TEST(Morton, KeyIncreasesAlongEachAxis) {
  auto key_along = [](int axis, std::uint32_t t, std::uint32_t u, std::uint32_t w) {
    return axis == 0 ? morton_key(t, u, w)
                     : (axis == 1 ? morton_key(u, t, w) : morton_key(u, w, t));
  };
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::uint32_t> value(0, kMortonAxisMax);
  for (int axis = 0; axis < 3; ++axis)
    for (int n = 0; n < 200; ++n) {
      const std::uint32_t u = value(rng), w = value(rng);
      // A random run of 200 consecutive coordinates.
      const std::uint32_t start =
          std::uniform_int_distribution<std::uint32_t>(0, kMortonAxisMax - 200)(rng);
      for (std::uint32_t t = start; t < start + 200; ++t)
        ASSERT_LT(key_along(axis, t, u, w), key_along(axis, t + 1, u, w))
            << "axis " << axis << " at " << t;
      // Every carry across a power of two, where most bits change at once.
      for (std::uint32_t k = 1; k < kMortonAxisBits; ++k) {
        const std::uint32_t t = (1u << k) - 1;
        ASSERT_LT(key_along(axis, t, u, w), key_along(axis, t + 1, u, w))
            << "axis " << axis << " at " << t;
      }
      // Far apart along the axis, too.
      const std::uint32_t a = value(rng), b = value(rng);
      if (a != b) {
        ASSERT_EQ(key_along(axis, a, u, w) < key_along(axis, b, u, w), a < b)
            << "axis " << axis << " " << a << " vs " << b;
      }
    }
}

}  // namespace
}  // namespace upf
