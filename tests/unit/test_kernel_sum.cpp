// The vectorised density sum of solvers/fluid/kernel_sum.h against the plain loop it replaces:
// every pair's term has the plain loop's bits (the branch-free cubic spline is value() bit for
// bit, Monaghan 1992's kernel either way), and the sums differ only by the order of their float
// additions, for lists of every length around the chunk size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "framework/kernels/cubic_spline.h"
#include "solvers/fluid/kernel_sum.h"

namespace upf {
namespace {

bool same_bits(Real a, Real b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Distances around every branch of the kernel: 0, the tiny-distance guard of the gradient, the
// joint at H/2, the support H and beyond, and random ones.
std::vector<Real> probe_distances(Real h) {
  std::vector<Real> r = {0,
                         Real(1e-12) * h,
                         Real(1e-9) * h,
                         std::nextafter(Real(1e-9) * h, h),
                         Real(0.5) * h,
                         std::nextafter(Real(0.5) * h, Real(0)),
                         std::nextafter(Real(0.5) * h, h),
                         std::nextafter(h, Real(0)),
                         h,
                         std::nextafter(h, Real(2) * h),
                         Real(1.5) * h,
                         Real(1e30)};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.2);
  for (int n = 0; n < 20000; ++n) r.push_back(Real(u(rng) * double(h)));
  return r;
}

TEST(BranchFreeKernel, ValueHasTheBitsOfValue) {
  for (Real h : {Real(0.05), Real(1), Real(0.0375)}) {
    const CubicSplineKernel k{h};
    for (Real r : probe_distances(h))
      ASSERT_TRUE(same_bits(k.value_without_branches(r), k.value(r))) << "H=" << h << " r=" << r;
  }
}

// A particle at the origin and `count` neighbours at random offsets within 1.1 H (some outside
// the support, as predicted positions leave them), listed from slot `begin` on.
struct RandomList {
  std::vector<Vec3> x;
  std::vector<std::uint32_t> indices;
  std::vector<Real> weight;
  RandomList(const CubicSplineKernel& k, std::uint32_t begin, std::uint32_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.1, 1.1), positive(0.5, 2.0);
    const double h = k.support_radius();
    x.push_back(Vec3{});
    indices.assign(begin, 0);  // slots of another particle's list
    for (std::uint32_t n = 0; n < count; ++n) {
      x.push_back(Vec3{Real(u(rng) * h), Real(u(rng) * h), Real(u(rng) * h)});
      indices.push_back(std::uint32_t(x.size() - 1));
    }
    for (std::size_t j = 0; j < x.size(); ++j) weight.push_back(Real(positive(rng)));
  }
};

TEST(KernelSum, IsThePlainSumUpToTheOrderOfAdditions) {
  const CubicSplineKernel k{Real(0.05)};
  for (std::uint32_t count : {0u, 1u, 3u, 4u, 5u, 15u, 16u, 17u, 31u, 32u, 33u, 70u}) {
    const std::uint32_t begin = 3;
    const RandomList list(k, begin, count, 100 + count);
    double plain = 0, magnitude = 0;
    for (std::uint32_t s = begin; s < begin + count; ++s) {
      const std::uint32_t j = list.indices[s];
      const Real term = list.weight[j] * k.value(norm(list.x[0] - list.x[j]));
      plain += double(term);
      magnitude += std::abs(double(term));
    }
    const Real sum = kernel_sum(k, list.x[0], list.x.data(), list.indices.data(), begin,
                                begin + count, ArrayWeight{list.weight.data()});
    EXPECT_NEAR(
        double(sum), plain,
        2.0 * double(count) * double(std::numeric_limits<Real>::epsilon()) * magnitude + 1e-30)
        << count << " neighbours";
    if (count == 0) {
      EXPECT_TRUE(same_bits(sum, Real(0)));
    }
  }
}

}  // namespace
}  // namespace upf
