// Reductions whose result does not depend on the thread count or on the order of the values
// (deterministic_sum.h, DESIGN.md "Determinism").
//
// The data are chosen so that order matters for ordinary floating-point sums (checked below):
// otherwise "the same bits" would prove nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "framework/core/deterministic_sum.h"
#include "framework/executors/cpu/cpu_executor.h"

namespace upf {
namespace {

constexpr std::size_t kCount = 200003;  // not a multiple of the 4096 block

// Signed values over nine decades (1e-6 .. 1e3): sums of these lose low bits differently in
// different orders.
std::vector<double> spread_values(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> exponent(-6, 3), unit(0, 1);
  std::vector<double> v(n);
  for (double& x : v) x = (unit(rng) < 0.5 ? -1 : 1) * std::pow(10.0, exponent(rng));
  return v;
}

long double reference_sum(const std::vector<double>& v) {
  long double s = 0;
  for (double x : v) s += x;
  return s;
}

long double sum_of_magnitudes(const std::vector<double>& v) {
  long double s = 0;
  for (double x : v) s += std::abs(x);
  return s;
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

double naive_sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(DeterministicSum, FixedPointSameBitsForAnyThreadCountAndOrder) {
  const std::vector<double> v = spread_values(kCount, 1);
  std::vector<double> reversed(v.rbegin(), v.rend());
  // Precondition: a plain double sum of these values depends on the order.
  ASSERT_NE(bits(naive_sum(v)), bits(naive_sum(reversed)));
  std::vector<double> shuffled = v;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(2));
  auto sum = [](const std::vector<double>& values, int threads) {
    return fixed_point_sum(CpuExecutor(threads), values.size(),
                           [&](std::size_t i) { return values[i]; });
  };
  const double one = sum(v, 1);
  EXPECT_EQ(bits(sum(v, 2)), bits(one));
  EXPECT_EQ(bits(sum(v, 3)), bits(one));
  EXPECT_EQ(bits(sum(v, 8)), bits(one));
  EXPECT_EQ(bits(sum(reversed, 1)), bits(one));
  EXPECT_EQ(bits(sum(reversed, 2)), bits(one));
  EXPECT_EQ(bits(sum(shuffled, 2)), bits(one));
}

// Each value is rounded to the nearest multiple of 2^-f (error <= 2^-(f+1)); the integer sum is
// exact; the final conversion to double adds at most one rounding (2^-53 relative).
TEST(DeterministicSum, FixedPointCloseToLongDoubleReference) {
  const std::vector<double> v = spread_values(kCount, 3);
  for (int fraction_bits : {32, 24, 16}) {
    const double got = fixed_point_sum(
        CpuExecutor(2), v.size(), [&](std::size_t i) { return v[i]; }, fraction_bits);
    const long double want = reference_sum(v);
    const double bound = double(v.size()) * std::ldexp(1.0, -(fraction_bits + 1)) +
                         std::abs(double(want)) * std::ldexp(1.0, -52);
    EXPECT_NEAR(got, double(want), bound) << fraction_bits << " fraction bits";
    // The result is a whole number of 2^-f units.
    const double units = got * std::ldexp(1.0, fraction_bits);
    EXPECT_EQ(units, std::round(units)) << fraction_bits << " fraction bits";
  }
}

// Values that are exact in fixed point sum exactly: k / 1024 for integers k.
TEST(DeterministicSum, FixedPointIsExactForRepresentableValues) {
  std::mt19937 rng(4);
  std::uniform_int_distribution<std::int64_t> k(-1000000, 1000000);
  std::vector<std::int64_t> ints(kCount);
  for (auto& x : ints) x = k(rng);
  const std::int64_t exact = std::accumulate(ints.begin(), ints.end(), std::int64_t(0));
  const double got = fixed_point_sum(CpuExecutor(2), ints.size(),
                                     [&](std::size_t i) { return double(ints[i]) / 1024; });
  EXPECT_EQ(got, double(exact) / 1024);
  // Float inputs (Real by default) convert exactly too.
  const double from_float = fixed_point_sum(CpuExecutor(2), 4, [](std::size_t i) {
    const float f[] = {0.5f, -0.25f, 1024.125f, 3.0f};
    return f[i];
  });
  EXPECT_EQ(from_float, 1027.375);
}

// A hostile checkpoint can hold finite values whose error terms overflow 64-bit fixed point
// (ASan+UBSan's checkpoint fuzzer found 9.7e33): they saturate, NaN upwards, so the sum reads as
// huge (a stopping test fails) instead of converting out of range, and it stays order-free.
TEST(DeterministicSum, FixedPointSaturatesHugeAndNotFiniteTerms) {
  const std::vector<double> values = {1.0, 9.7e33, std::nan(""), -1e300, 2.5};
  const auto sum = [&](int threads) {
    return fixed_point_sum(CpuExecutor(threads), values.size(),
                           [&](std::size_t i) { return values[i]; });
  };
  const double limit = fixed_point_term_limit(values.size()) / 4294967296.0;  // in value units
  EXPECT_DOUBLE_EQ(sum(1), limit + 1.0 + 2.5);  // huge + NaN - huge: one limit left
  EXPECT_EQ(std::bit_cast<std::uint64_t>(sum(1)), std::bit_cast<std::uint64_t>(sum(2)));
  const std::vector<double> all_nan(8, std::nan(""));
  EXPECT_GT(
      fixed_point_sum(CpuExecutor(2), all_nan.size(), [&](std::size_t i) { return all_nan[i]; }),
      1e6);
}

TEST(DeterministicSum, BlockSumSameBitsForAnyThreadCount) {
  const std::vector<double> v = spread_values(kCount, 5);
  auto sum = [&](int threads) {
    return block_sum(CpuExecutor(threads), v.size(), [&](std::size_t i) { return v[i]; });
  };
  const double one = sum(1);
  EXPECT_EQ(bits(sum(2)), bits(one));
  EXPECT_EQ(bits(sum(3)), bits(one));
  EXPECT_EQ(bits(sum(8)), bits(one));
}

// The documented algorithm, written out: blocks of 4096 summed in index order, then the block
// sums in index order. block_sum must give exactly these bits.
TEST(DeterministicSum, BlockSumIsBlocksOf4096InIndexOrder) {
  const std::vector<double> v = spread_values(kCount, 6);
  double total = 0;
  for (std::size_t b = 0; b < v.size(); b += 4096) {
    double s = 0;
    for (std::size_t i = b; i < std::min(v.size(), b + 4096); ++i) s += v[i];
    total += s;
  }
  const double got = block_sum(CpuExecutor(2), v.size(), [&](std::size_t i) { return v[i]; });
  EXPECT_EQ(bits(got), bits(total));
  // And it differs from the plain left-to-right sum on this data (so the check above has teeth).
  EXPECT_NE(bits(total), bits(naive_sum(v)));
}

// Recursive summation error (Higham, "Accuracy and Stability of Numerical Algorithms", 2002,
// eq. 4.4): |error| <= (m - 1) u sum|x| for m terms; here at most 4096 + (number of blocks)
// additions lie on any path, u = 2^-53.
TEST(DeterministicSum, BlockSumCloseToLongDoubleReference) {
  const std::vector<double> v = spread_values(kCount, 7);
  const double got = block_sum(CpuExecutor(2), v.size(), [&](std::size_t i) { return v[i]; });
  const double additions = 4096.0 + double(v.size() / 4096 + 1);
  const double bound = additions * std::ldexp(1.0, -53) * double(sum_of_magnitudes(v));
  EXPECT_NEAR(got, double(reference_sum(v)), bound);
}

TEST(DeterministicSum, EmptyAndSmallInputs) {
  auto one = [](std::size_t) { return 1.0; };
  EXPECT_EQ(fixed_point_sum(CpuExecutor(2), 0, one), 0.0);
  EXPECT_EQ(block_sum(CpuExecutor(2), 0, one), 0.0);
  EXPECT_EQ(fixed_point_sum(CpuExecutor(2), 3, one), 3.0);
  EXPECT_EQ(block_sum(CpuExecutor(2), 3, one), 3.0);
  EXPECT_EQ(block_sum(CpuExecutor(2), 4097, one), 4097.0);
}

}  // namespace
}  // namespace upf
