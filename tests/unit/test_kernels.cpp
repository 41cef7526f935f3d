// Unit tests of the SPH kernels against their defining papers:
//   cubic spline: Monaghan 1992, "Smoothed particle hydrodynamics", Annu. Rev. Astron.
//                 Astrophys. 30, written with the support radius H (= 2h);
//   poly6, spiky, viscosity: Müller, Charypar & Gross 2003, "Particle-based fluid simulation for
//                 interactive applications", SCA 2003, eqs. (20)-(22).
//
// The kernels compute in Real (float by default); the test computes its references in double and
// sets tolerances from the float round-off that the kernel itself makes (kEps below).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "framework/kernels/cubic_spline.h"
#include "framework/kernels/muller_kernels.h"

namespace upf {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Unit round-off of the type the kernels compute in.
constexpr double kEps = std::numeric_limits<Real>::epsilon();

// Support radii: a typical one, one, and one that is not a "round" float.
const std::array<double, 3> kSupportRadii = {0.1, 1.0, 0.0375};

using RadialFunction = std::function<double(double r)>;
using VectorFunction = std::function<Vec3(const Vec3& r)>;

std::string sci(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", v);
  return buffer;
}

Vec3 vec(double x, double y, double z) {
  return {Real(x), Real(y), Real(z)};
}

// ∫ W dV by the midpoint rule on a cubic lattice of spacing H/cells_per_h covering [-H, H]^3.
// The lattice is offset by half a cell, so no node sits at r = 0 (the viscosity kernel has a 1/r
// singularity there, integrable in 3-D).
double lattice_integral(const RadialFunction& w, double h, int cells_per_h) {
  const double dx = h / cells_per_h;
  const int n = 2 * cells_per_h;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -h + (i + 0.5) * dx;
    for (int j = 0; j < n; ++j) {
      const double y = -h + (j + 0.5) * dx;
      for (int k = 0; k < n; ++k) {
        const double z = -h + (k + 0.5) * dx;
        sum += w(std::sqrt(x * x + y * y + z * z));
      }
    }
  }
  return sum * dx * dx * dx;
}

// Random points strictly inside the support: |r| uniform in [lo, hi] * H, direction uniform.
std::vector<Vec3> random_points(double h, double lo, double hi, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> radius(lo * h, hi * h);
  std::vector<Vec3> points;
  for (int n = 0; n < count; ++n) {
    double d[3] = {normal(rng), normal(rng), normal(rng)};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double r = radius(rng);
    points.push_back(vec(d[0] / len * r, d[1] / len * r, d[2] / len * r));
  }
  return points;
}

double length(const Vec3& v) {
  return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

// Checks grad(r) against the central difference (W(r + d e_a) - W(r - d e_a)) / (2 d) of the
// kernel's own values along each axis a, which also checks the sign convention (gradient with
// respect to r = x_i - x_j), at 2000 random points with min_radius <= |r|/H <= 0.99. Error allowed:
// rel * |grad| + abs * max|grad W| (the abs part covers float round-off of the values divided by 2d
// where the gradient itself vanishes).
void expect_gradient_matches_differences(const RadialFunction& value, const VectorFunction& grad,
                                         double h, double max_gradient, double rel, double abs,
                                         double min_radius, const std::string& name) {
  const double d = 1e-3 * h;
  double worst = 0;
  for (const Vec3& r : random_points(h, min_radius, 0.99, 2000, 17)) {
    const Vec3 g = grad(r);
    double fd[3];
    for (int a = 0; a < 3; ++a) {
      double plus[3] = {r.x, r.y, r.z}, minus[3] = {r.x, r.y, r.z};
      plus[a] += d;
      minus[a] -= d;
      const double rp = std::sqrt(plus[0] * plus[0] + plus[1] * plus[1] + plus[2] * plus[2]);
      const double rm = std::sqrt(minus[0] * minus[0] + minus[1] * minus[1] + minus[2] * minus[2]);
      fd[a] = (value(rp) - value(rm)) / (2 * d);
    }
    const double err = std::sqrt((g.x - fd[0]) * (g.x - fd[0]) + (g.y - fd[1]) * (g.y - fd[1]) +
                                 (g.z - fd[2]) * (g.z - fd[2]));
    const double allowed = rel * length(g) + abs * max_gradient;
    worst = std::max(worst, err / allowed);
    ASSERT_LE(err, allowed) << name << " H=" << h << " at r=(" << r.x << ", " << r.y << ", " << r.z
                            << ") |r|/H=" << length(r) / h << ": analytic (" << g.x << ", " << g.y
                            << ", " << g.z << ") vs differences (" << fd[0] << ", " << fd[1] << ", "
                            << fd[2] << ")";
  }
  ::testing::Test::RecordProperty(name + "_worst_error_over_allowed", sci(worst));
}

// --- Normalisation: ∫ W dV = 1, the defining property of an SPH kernel (Monaghan 1992, Sect. 2;
// Müller et al. 2003, Sect. 3) ------------------------------------------------------------------

TEST(KernelNormalisation, CubicSplineIntegratesToOne) {
  for (double h : kSupportRadii) {
    const CubicSplineKernel k{Real(h)};
    const double integral = lattice_integral([&](double r) { return k.value(Real(r)); }, h, 40);
    EXPECT_NEAR(integral, 1.0, 1e-3) << "H=" << h;
    RecordProperty("integral_minus_one_H" + std::to_string(h), sci(integral - 1));
  }
}

TEST(KernelNormalisation, Poly6IntegratesToOne) {
  for (double h : kSupportRadii) {
    const MullerKernels k{Real(h)};
    const double integral = lattice_integral([&](double r) { return k.poly6(Real(r)); }, h, 40);
    EXPECT_NEAR(integral, 1.0, 1e-3) << "H=" << h;
    RecordProperty("integral_minus_one_H" + std::to_string(h), sci(integral - 1));
  }
}

TEST(KernelNormalisation, SpikyIntegratesToOne) {
  for (double h : kSupportRadii) {
    const MullerKernels k{Real(h)};
    const double integral = lattice_integral([&](double r) { return k.spiky(Real(r)); }, h, 40);
    EXPECT_NEAR(integral, 1.0, 1e-3) << "H=" << h;
    RecordProperty("integral_minus_one_H" + std::to_string(h), sci(integral - 1));
  }
}

TEST(KernelNormalisation, ViscosityIntegratesToOne) {
  for (double h : kSupportRadii) {
    const MullerKernels k{Real(h)};
    const double integral = lattice_integral([&](double r) { return k.viscosity(Real(r)); }, h, 40);
    EXPECT_NEAR(integral, 1.0, 1e-3) << "H=" << h;
    RecordProperty("integral_minus_one_H" + std::to_string(h), sci(integral - 1));
  }
}

// --- Values against the papers' closed forms, evaluated in double ----------------------------

TEST(KernelValues, MatchClosedFormsOfThePapers) {
  for (double h : kSupportRadii) {
    const CubicSplineKernel cubic{Real(h)};
    const MullerKernels muller{Real(h)};
    const double h3 = h * h * h, h6 = h3 * h3, h9 = h6 * h3;
    // Monaghan 1992 (support H = 2h): k = 8/(pi H^3),
    // W = k (6q^3 - 6q^2 + 1) for q <= 1/2, W = 2k (1 - q)^3 for 1/2 < q <= 1.
    auto cubic_ref = [&](double r) {
      const double q = r / h, k = 8 / (kPi * h3);
      return q <= 0.5 ? k * (6 * q * q * q - 6 * q * q + 1) : 2 * k * std::pow(1 - q, 3);
    };
    // Müller et al. 2003 eq. (20): W_poly6 = 315/(64 pi H^9) (H^2 - r^2)^3.
    auto poly6_ref = [&](double r) { return 315 / (64 * kPi * h9) * std::pow(h * h - r * r, 3); };
    // Müller et al. 2003 eq. (21): W_spiky = 15/(pi H^6) (H - r)^3.
    auto spiky_ref = [&](double r) { return 15 / (kPi * h6) * std::pow(h - r, 3); };
    // Müller et al. 2003 eq. (22): W_visc = 15/(2 pi H^3) (-r^3/(2H^3) + r^2/H^2 + H/(2r) - 1),
    // in the cancellation-free form (1 - q)^3 (1 + q) / (2q) of the bracket.
    auto visc_ref = [&](double r) {
      const double q = r / h;
      return 15 / (2 * kPi * h3) * std::pow(1 - q, 3) * (1 + q) / (2 * q);
    };
    // Müller et al. 2003 eq. (22): lap W_visc = 45/(pi H^6) (H - r).
    auto visc_lap_ref = [&](double r) { return 45 / (kPi * h6) * (h - r); };

    // Float evaluation of a polynomial whose terms are O(1) times the scale leaves an absolute
    // error of a few eps times that scale; relative 16 eps elsewhere.
    auto check = [&](const char* name, double got, double want, double scale, double r) {
      EXPECT_NEAR(got, want, 16 * kEps * (std::abs(want) + scale))
          << name << " H=" << h << " r/H=" << r / h;
    };
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 2000; ++n) {
      const double r = double(Real(h * unit(rng)));  // exactly representable in Real
      check("cubic", cubic.value(Real(r)), cubic_ref(r), cubic_ref(0), r);
      check("poly6", muller.poly6(Real(r)), poly6_ref(r), poly6_ref(0), r);
      check("spiky", muller.spiky(Real(r)), spiky_ref(r), spiky_ref(0), r);
      check("viscosity laplacian", muller.viscosity_laplacian(Real(r)), visc_lap_ref(r),
            visc_lap_ref(0), r);
      // The bracket's terms are O(1 + 1/(2q)): that is the scale of its round-off.
      if (r > 0)
        check("viscosity", muller.viscosity(Real(r)), visc_ref(r),
              15 / (2 * kPi * h3) * (1 + h / (2 * r)), r);
    }
    // W(0), where the formulas are easiest to read off the papers.
    EXPECT_NEAR(cubic.value(Real(0)), 8 / (kPi * h3), 4 * kEps * 8 / (kPi * h3));
    EXPECT_NEAR(muller.poly6(Real(0)), 315 / (64 * kPi * h3), 8 * kEps * 315 / (64 * kPi * h3));
    EXPECT_NEAR(muller.spiky(Real(0)), 15 / (kPi * h3), 8 * kEps * 15 / (kPi * h3));
  }
}

// --- Gradients against central differences of the values --------------------------------------

// Central differences with step d = 1e-3 H have a truncation error d^2/6 |W'''| <= ~1e-5 of the
// gradient scale for these piecewise polynomials, and a round-off error ~ eps W / d from the
// float values, ~1e-4 of the gradient scale; the analytic gradient itself is exact to a few eps.
constexpr double kGradientRel = 3e-4;
constexpr double kGradientAbs = 1.5e-4;

TEST(KernelGradient, CubicSplineMatchesFiniteDifferences) {
  for (double h : kSupportRadii) {
    const CubicSplineKernel k{Real(h)};
    // max |dW/dr| = 48/(pi H^4) * max q|3q - 2| = 48/(pi H^4) / 3 at q = 1/3 (Monaghan 1992).
    const double max_gradient = 48 / (kPi * h * h * h * h) / 3;
    expect_gradient_matches_differences([&](double r) { return k.value(Real(r)); },
                                        [&](const Vec3& r) { return k.gradient(r); }, h,
                                        max_gradient, kGradientRel, kGradientAbs, 0.01, "cubic");
  }
}

TEST(KernelGradient, Poly6MatchesFiniteDifferences) {
  for (double h : kSupportRadii) {
    const MullerKernels k{Real(h)};
    // |grad W| = 6 * 315/(64 pi H^9) r (H^2 - r^2)^2, largest at r = H/sqrt(5).
    const double rm = h / std::sqrt(5.0);
    const double max_gradient =
        6 * 315 / (64 * kPi * std::pow(h, 9)) * rm * std::pow(h * h - rm * rm, 2);
    expect_gradient_matches_differences([&](double r) { return k.poly6(Real(r)); },
                                        [&](const Vec3& r) { return k.poly6_gradient(r); }, h,
                                        max_gradient, kGradientRel, kGradientAbs, 0.01, "poly6");
  }
}

TEST(KernelGradient, SpikyMatchesFiniteDifferences) {
  for (double h : kSupportRadii) {
    const MullerKernels k{Real(h)};
    // |grad W| = 45/(pi H^6) (H - r)^2, largest at r -> 0 (Müller et al. 2003 eq. 21).
    const double max_gradient = 45 / (kPi * std::pow(h, 4));
    // W_spiky is a cone at r = 0 (its gradient does not vanish there), so the differences'
    // truncation error grows like (d / r)^2: stay at r >= 0.05 H.
    expect_gradient_matches_differences([&](double r) { return k.spiky(Real(r)); },
                                        [&](const Vec3& r) { return k.spiky_gradient(r); }, h,
                                        max_gradient, kGradientRel, kGradientAbs, 0.05, "spiky");
  }
}

// value_and_gradient (one square root for both, what the fluid loops call) gives the same value
// and, up to the order of its float operations, the same gradient as value() and gradient().
TEST(KernelGradient, CubicSplineValueAndGradientAgreeWithSeparateCalls) {
  for (double h : kSupportRadii) {
    const CubicSplineKernel k{Real(h)};
    for (const Vec3& r : random_points(h, 0.0, 1.5, 4000, 29)) {
      Vec3 g{Real(7), Real(7), Real(7)};  // must be overwritten, also with zero
      const Real w = k.value_and_gradient(r, g);
      const Vec3 want = k.gradient(r);
      EXPECT_NEAR(w, k.value(r), 2 * kEps * std::abs(k.value(r))) << "H=" << h;
      EXPECT_LE(length(g - want), 8 * kEps * length(want)) << "H=" << h << " |r|/H=" << norm(r) / h;
    }
    Vec3 g{Real(7), Real(7), Real(7)};
    EXPECT_EQ(k.value_and_gradient(Vec3{}, g), k.value(Real(0)));
    EXPECT_EQ(g, Vec3{});  // no direction at r = 0
  }
}

// The Laplacian of a radial function is (1/r) d^2(r W)/dr^2. For the viscosity kernel r W(r) is a
// quartic polynomial in r (the H/(2r) term becomes a constant), so Richardson's combination
// (4 D(d) - D(2d)) / 3 of central second differences D is exact up to round-off.
TEST(KernelLaplacian, ViscosityMatchesFiniteDifferences) {
  for (double h : kSupportRadii) {
    const MullerKernels k{Real(h)};
    auto rw = [&](double r) { return r * double(k.viscosity(Real(r))); };
    const double d = 0.04 * h;
    auto second = [&](double r, double step) {
      return (rw(r + step) - 2 * rw(r) + rw(r - step)) / (step * step);
    };
    double worst = 0;
    for (int n = 0; n <= 80; ++n) {
      const double r = h * (0.1 + 0.8 * (n + 0.5) / 81);  // r in (0.1 H, 0.9 H)
      const double fd = (4 * second(r, d) - second(r, 2 * d)) / 3 / r;
      const double lap = k.viscosity_laplacian(Real(r));
      // Round-off: W is accurate to a few eps of its terms, O(15/(2 pi H^3) H/r); a second
      // difference divides that by d^2: here at most ~3e-4 of the Laplacian (smallest: at 0.9 H).
      const double allowed = 1e-3 * std::abs(lap);
      worst = std::max(worst, std::abs(fd - lap) / allowed);
      EXPECT_NEAR(fd, lap, allowed) << "H=" << h << " r/H=" << r / h;
    }
    RecordProperty("viscosity_laplacian_worst_error_over_allowed_H" + std::to_string(h),
                   sci(worst));
  }
}

// --- Compact support: value and gradient are exactly 0 at r >= H -------------------------------

void expect_zero_outside(double h_in, const Vec3& r) {
  const Real h = Real(h_in);
  const CubicSplineKernel cubic{h};
  const MullerKernels muller{h};
  const Real rl = norm(r);
  ASSERT_GE(rl, h);
  // Compact support: W(r) = 0 for r >= H (Monaghan 1992; Müller et al. 2003 eqs. 20-22).
  EXPECT_EQ(cubic.value(rl), Real(0)) << "H=" << h << " r=" << rl;
  EXPECT_EQ(cubic.value(r), Real(0)) << "H=" << h << " r=" << rl;
  EXPECT_EQ(cubic.gradient(r), Vec3{}) << "H=" << h << " r=" << rl;
  Vec3 g{Real(7), Real(7), Real(7)};
  EXPECT_EQ(cubic.value_and_gradient(r, g), Real(0)) << "H=" << h << " r=" << rl;
  EXPECT_EQ(g, Vec3{}) << "H=" << h << " r=" << rl;
  EXPECT_EQ(muller.poly6(rl), Real(0)) << "H=" << h << " r=" << rl;
  EXPECT_EQ(muller.poly6_gradient(r), Vec3{}) << "H=" << h << " r=" << rl;
  EXPECT_EQ(muller.spiky(rl), Real(0)) << "H=" << h << " r=" << rl;
  EXPECT_EQ(muller.spiky_gradient(r), Vec3{}) << "H=" << h << " r=" << rl;
  EXPECT_EQ(muller.viscosity(rl), Real(0)) << "H=" << h << " r=" << rl;
  EXPECT_EQ(muller.viscosity_laplacian(rl), Real(0)) << "H=" << h << " r=" << rl;
}

TEST(KernelSupport, ZeroAtAndBeyondSupportRadius) {
  for (double h_in : kSupportRadii) {
    const Real h = Real(h_in);
    const Real just_above = std::nextafter(h, std::numeric_limits<Real>::max());
    for (Real r : {h, just_above, Real(1.5) * h, Real(2) * h, Real(1e3) * h}) {
      expect_zero_outside(h, Vec3{r, 0, 0});
      expect_zero_outside(h, Vec3{0, -r, 0});
      expect_zero_outside(h, Vec3{0, 0, r});
    }
    // Random directions, kept where |r| as computed in Real is >= H.
    for (const Vec3& r : random_points(h, 1.0, 3.0, 500, 23))
      if (norm(r) >= h && squared_norm(r) >= h * h) expect_zero_outside(h, r);
  }
}

// The same at r = H exactly for many support radii: the cutoff must not depend on how r/H
// rounds. The neighbour grid excludes pairs with r >= H, so a kernel that leaks there would make
// sums depend on whether a pair at exactly r = H is listed.
TEST(KernelSupport, ZeroAtSupportRadiusForManyRadii) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> radius(Real(0.01), Real(1));
  for (int n = 0; n < 200; ++n) {
    const Real h = radius(rng);
    expect_zero_outside(h, Vec3{h, 0, 0});
    if (HasFailure()) return;  // one reproducer is enough
  }
}

// --- Shape: non-negative and non-increasing in r ------------------------------------------------

TEST(KernelShape, NonNegativeAndNonIncreasing) {
  for (double h : kSupportRadii) {
    const CubicSplineKernel cubic{Real(h)};
    const MullerKernels muller{Real(h)};
    struct Profile {
      const char* name;
      std::function<Real(Real)> w;
      double scale;  // the size of the formula's terms: float round-off is relative to it
    };
    const double h3 = h * h * h;
    const std::vector<Profile> profiles = {
        {"cubic", [&](Real r) { return cubic.value(r); }, 8 / (kPi * h3)},
        {"poly6", [&](Real r) { return muller.poly6(r); }, 315 / (64 * kPi * h3)},
        {"spiky", [&](Real r) { return muller.spiky(r); }, 15 / (kPi * h3)},
        {"viscosity", [&](Real r) { return muller.viscosity(r); }, 15 / (2 * kPi * h3)},
        {"viscosity laplacian", [&](Real r) { return muller.viscosity_laplacian(r); },
         45 / (kPi * h3 * h * h)},
    };
    for (const Profile& p : profiles) {
      // All four kernels (and the viscosity Laplacian, 45/(pi H^6)(H - r)) are >= 0 and
      // decreasing in r on [0, H] by their closed forms (Monaghan 1992; Müller et al. 2003).
      // Exact non-negativity; monotonicity up to the float round-off of evaluating terms of size
      // `scale` (a few eps of it: near H the viscosity bracket cancels to O((1 - q)^3)). Sampled
      // from r = H/20000 (W_visc is undefined at 0) to 1.2 H.
      const int steps = 20000;
      Real previous = std::numeric_limits<Real>::max();
      int increases = 0;
      for (int n = 1; n <= steps + steps / 5; ++n) {
        const Real r = Real(h * n / steps);
        const Real w = p.w(r);
        EXPECT_GE(w, Real(0)) << p.name << " H=" << h << " r/H=" << r / h;
        EXPECT_LE(double(w), double(previous) + 8 * kEps * p.scale)
            << p.name << " H=" << h << " r/H=" << r / h;
        increases += w > previous;
        previous = w;
        if (HasFailure()) return;
      }
      // Strict decrease wherever the true slope is well above round-off: at the quarter points.
      EXPECT_GT(p.w(Real(0.25 * h)), p.w(Real(0.5 * h))) << p.name;
      EXPECT_GT(p.w(Real(0.5 * h)), p.w(Real(0.75 * h))) << p.name;
      EXPECT_GT(p.w(Real(0.75 * h)), Real(0)) << p.name;
      RecordProperty(std::string(p.name) + "_roundoff_increases", increases);
    }
  }
}

}  // namespace
}  // namespace upf
