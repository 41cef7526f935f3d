// NeighbourGrid::find_neighbours against independent exact references, on clouds of 100,000
// particles: uniform, clustered (Gaussian blobs of very different density) and sparse (a huge,
// mostly empty box with isolated pairs at a distance of about the radius).
//
// The neighbour relation is the grid's own contract (neighbour_grid.h): j is a neighbour of i when
// i != j, type(i) is in the query mask, type(j) is in the target mask and
// squared_norm(x_i - x_j) < radius^2, computed in Real. The references evaluate exactly that
// predicate, so the sets must be equal exactly, not approximately.
//
// Reference 1 (every particle): a sweep along x. Particles are sorted by x; for each one the sweep
// visits the following particles while fl(x_j - x_i) < radius. This is exact: if
// |fl(x_j - x_i)| >= radius then fl(dx^2) >= fl(radius^2), and adding the non-negative dy^2, dz^2
// in rounded arithmetic cannot decrease the sum, so squared_norm >= radius^2. (Same pre-filter on
// |dy|, |dz|.)
// Reference 2 (about 1000 queries per cloud): O(N) brute force over all 100,000 particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "framework/executors/cpu/cpu_executor.h"
#include "framework/neighbours/neighbour_grid.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf {
namespace {

constexpr std::size_t kCloudSize = 100000;
// A support radius that is not a power of two, as in real scenes (h = 0.1 m).
constexpr Real kCellSize = Real(0.1);
constexpr TypeMask kFrozenMask = mask_of(ParticleType::Frozen);
constexpr TypeMask kGranularMask = mask_of(ParticleType::Granular);

// --- Clouds ------------------------------------------------------------------------------------

// Liquid 60 %, Frozen 30 %, Granular 10 %: the masks then select proper subsets on both sides.
ParticleType random_type(std::mt19937& rng) {
  const int u = std::uniform_int_distribution<int>(0, 9)(rng);
  return u < 6 ? ParticleType::Liquid : (u < 9 ? ParticleType::Frozen : ParticleType::Granular);
}

void add_particle(Particles& p, const Vec3& x, std::mt19937& rng) {
  p.add(x, Vec3{}, Real(1), random_type(rng), MaterialId(0));
}

// Uniform random in a box elongated along x ([0, 300h] x [0, 7h] x [0, 7h], about 28
// neighbours per particle), which keeps the sweep's window to ~330 particles.
Particles uniform_cloud() {
  std::mt19937 rng(101);
  std::uniform_real_distribution<Real> ux(0, 300 * kCellSize), uyz(0, 7 * kCellSize);
  Particles p;
  p.reserve(kCloudSize);
  while (p.size() < kCloudSize) {
    const Real x = ux(rng), y = uyz(rng), z = uyz(rng);
    add_particle(p, Vec3{x, y, z}, rng);
  }
  return p;
}

// Gaussian blobs of very different density along x plus a thin uniform background: the densest
// blob has ~165 neighbours per particle at its centre, the widest ~0.02.
Particles clustered_cloud() {
  struct Blob {
    double cx, sigma;
    std::size_t count;
  };
  const Blob blobs[] = {{0, 2, 5000}, {20, 6, 15000}, {60, 25, 30000}, {150, 100, 45000}};
  std::mt19937 rng(202);
  std::normal_distribution<double> normal;
  const double h = double(kCellSize);
  Particles p;
  p.reserve(kCloudSize);
  for (const Blob& b : blobs)
    for (std::size_t n = 0; n < b.count; ++n) {
      const Real x = Real(h * (b.cx + b.sigma * normal(rng)));
      const Real y = Real(h * b.sigma * normal(rng));
      const Real z = Real(h * b.sigma * normal(rng));
      add_particle(p, Vec3{x, y, z}, rng);
    }
  std::uniform_real_distribution<Real> ux(-50 * kCellSize, 400 * kCellSize),
      uyz(-60 * kCellSize, 60 * kCellSize);
  while (p.size() < kCloudSize) {
    const Real x = ux(rng), y = uyz(rng), z = uyz(rng);
    add_particle(p, Vec3{x, y, z}, rng);
  }
  return p;
}

// The largest float b > a with fl(b - a) < d (inside = true), or the next float after it: a pair
// right at the edge of the radius along one axis.
Real partner_at(Real a, Real d, bool inside) {
  const Real up = std::numeric_limits<Real>::max(), down = std::numeric_limits<Real>::lowest();
  Real b = a + d;
  while (b - a >= d) b = std::nextafter(b, down);
  while (std::nextafter(b, up) - a < d) b = std::nextafter(b, up);
  return inside ? b : std::nextafter(b, up);
}

// A huge, mostly empty box: a corner particle at (-1000, -1000, -1000), the rest in
// [-999, 999]^3 (8e12 cells of 0.1 for 1e5 particles), and constructed particles first:
//  - 24 "rounding" pairs: at a distance just below the radius along one axis, placed (by search)
//    where x - origin, rounded to float, puts the two particles two cells apart. The grid's
//    origin is min - cell = -1000.1 here, so x - origin is ~1000 and has a float spacing of 6e-5,
//    much coarser than that of x itself near 0;
//  - 3000 pairs at the edge of the radius along an axis (3/4 just inside, 1/4 just outside),
//    half of them straddling +-2^k, where the float spacing changes;
//  - 1000 pairs at |r| = radius (1 - u 1e-6) in random directions;
//  - 300 coincident pairs (distance 0);
//  - 7 particles so far out that their cell coordinates exceed the 21-bit Morton range and are
//    clamped (neighbour_grid.cpp promises exact lists for them too).
struct SparseCloud {
  Particles particles;
  std::size_t constructed = 0;  // particles [0, constructed) are the constructed ones
  std::size_t rounding_pairs = 0;
};

SparseCloud sparse_cloud() {
  std::mt19937 rng(303);
  std::uniform_real_distribution<Real> box(-999, 999);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> normal;
  SparseCloud cloud;
  Particles& p = cloud.particles;
  p.reserve(kCloudSize);
  auto random_point = [&] { return Vec3{box(rng), box(rng), box(rng)}; };
  add_particle(p, Vec3{-1000, -1000, -1000}, rng);

  // Rounding pairs. cell() mirrors how the grid computes a cell coordinate; it only steers the
  // search for hard inputs, the verdict comes from the references.
  const Real origin = Real(-1000) - kCellSize;
  auto cell = [&](Real x) { return std::floor(double(x - origin) / double(kCellSize)); };
  for (int axis = 0; axis < 3; ++axis)
    for (int found = 0, trials = 0; found < 8 && trials < 200000; ++trials) {
      const Real a = box(rng) / 128;
      const Real b = partner_at(a, kCellSize, true);
      if (cell(b) - cell(a) < 2) continue;
      Vec3 xa = random_point();
      xa[axis] = a;
      Vec3 xb = xa;
      xb[axis] = b;
      add_particle(p, xa, rng);
      add_particle(p, xb, rng);
      ++found;
      ++cloud.rounding_pairs;
    }
  // Axis-aligned edge pairs.
  for (int n = 0; n < 3000; ++n) {
    Vec3 a = random_point();
    const int axis = n % 3;
    if (n % 2 == 0) {  // across +-2^k, k in [-3, 9]
      const int k = std::uniform_int_distribution<int>(-3, 9)(rng);
      const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
      a[axis] = Real(sign * std::ldexp(1.0, k) - unit(rng) * double(kCellSize));
    }
    Vec3 b = a;
    b[axis] = partner_at(a[axis], kCellSize, n % 4 != 2);
    add_particle(p, a, rng);
    add_particle(p, b, rng);
  }
  // Random-direction pairs at just under the radius.
  for (int n = 0; n < 1000; ++n) {
    const Vec3 a = random_point();
    const double d[3] = {normal(rng), normal(rng), normal(rng)};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double r = double(kCellSize) * (1 - 1e-6 * unit(rng));
    add_particle(p, a, rng);
    add_particle(
        p, Vec3{Real(a.x + d[0] / len * r), Real(a.y + d[1] / len * r), Real(a.z + d[2] / len * r)},
        rng);
  }
  // Coincident pairs.
  for (int n = 0; n < 300; ++n) {
    const Vec3 a = random_point();
    add_particle(p, a, rng);
    add_particle(p, a, rng);
  }
  // Clamped far-away particles: 2.5e5 / 0.1 = 2.5e6 cells > 2^21. The float spacing there is
  // 1/64, so 0.09375, 0.078125 and 0.0625 are exact separations below the radius.
  const Real far = Real(2.5e5);
  const Vec3 far_points[] = {{far, 0, 0},
                             {far + Real(0.09375), 0, 0},
                             {far + Real(1000), 0, 0},
                             {far, far, far},
                             {far, far + Real(0.078125), far},
                             {far, far, far + Real(0.125)},
                             {far + Real(0.0625), far, far + Real(0.0625)}};
  for (const Vec3& x : far_points) add_particle(p, x, rng);
  cloud.constructed = p.size();
  while (p.size() < kCloudSize) add_particle(p, random_point(), rng);
  return cloud;
}

// --- References --------------------------------------------------------------------------------

// Exact neighbour sets of every particle (all types) in CSR form, in no particular order.
struct Reference {
  std::vector<std::uint32_t> offsets, indices;
  IndexRange of(std::size_t i) const {
    return {indices.data() + offsets[i], indices.data() + offsets[i + 1]};
  }
};

Reference sweep_reference(const Particles& p, Real radius) {
  const std::size_t n = p.size();
  const Real r2 = radius * radius;
  const Vec3* x = p.position.data();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return x[a].x < x[b].x || (x[a].x == x[b].x && a < b);
  });
  // Structure of arrays in sweep order: the loop below is the test's hot spot in Debug builds.
  std::vector<Real> sxv(n), syv(n), szv(n);
  for (std::size_t s = 0; s < n; ++s) {
    sxv[s] = x[order[s]].x;
    syv[s] = x[order[s]].y;
    szv[s] = x[order[s]].z;
  }
  const Real *sx = sxv.data(), *sy = syv.data(), *sz = szv.data();
  const std::uint32_t* so = order.data();
  std::vector<std::uint32_t> pair_i, pair_j;  // each pair once
  for (std::size_t a = 0; a < n; ++a) {
    const Real xa = sx[a], ya = sy[a], za = sz[a];
    for (std::size_t b = a + 1; b < n && sx[b] - xa < radius; ++b) {
      const Real dy = sy[b] - ya, dz = sz[b] - za;
      if (dy < radius && -dy < radius && dz < radius && -dz < radius &&
          squared_norm(x[so[a]] - x[so[b]]) < r2) {
        pair_i.push_back(so[a]);
        pair_j.push_back(so[b]);
      }
    }
  }
  Reference ref;
  ref.offsets.assign(n + 1, 0);
  for (std::size_t k = 0; k < pair_i.size(); ++k) {
    ++ref.offsets[pair_i[k] + 1];
    ++ref.offsets[pair_j[k] + 1];
  }
  for (std::size_t i = 0; i < n; ++i) ref.offsets[i + 1] += ref.offsets[i];
  ref.indices.resize(ref.offsets[n]);
  std::vector<std::uint32_t> fill(ref.offsets.begin(), ref.offsets.end() - 1);
  for (std::size_t k = 0; k < pair_i.size(); ++k) {
    ref.indices[fill[pair_i[k]]++] = pair_j[k];
    ref.indices[fill[pair_j[k]]++] = pair_i[k];
  }
  return ref;
}

// O(N) brute force for one particle (all types), sorted by index. The pre-filter on |dx| is exact
// (see the file comment) and only saves time in Debug builds.
std::vector<std::uint32_t> brute_force(const Particles& p, std::uint32_t i, Real radius) {
  const Real r2 = radius * radius;
  const Vec3* x = p.position.data();
  const Vec3 xi = x[i];
  const std::uint32_t n = std::uint32_t(p.size());
  std::vector<std::uint32_t> out;
  for (std::uint32_t j = 0; j < n; ++j) {
    const Real dx = x[j].x - xi.x;
    if (dx < radius && -dx < radius && j != i && squared_norm(xi - x[j]) < r2) out.push_back(j);
  }
  return out;
}

// --- Comparison --------------------------------------------------------------------------------

std::string describe_pair(const Particles& p, std::uint32_t i, std::uint32_t j, Real radius) {
  char buffer[512];
  const Vec3 a = p.position[i], b = p.position[j];
  std::snprintf(buffer, sizeof buffer,
                "pair (%u, %u): x_i = (%.9g, %.9g, %.9g), x_j = (%.9g, %.9g, %.9g), "
                "squared_norm = %a, radius^2 = %a, types %d -> %d",
                i, j, double(a.x), double(a.y), double(a.z), double(b.x), double(b.y), double(b.z),
                double(squared_norm(a - b)), double(radius * radius), int(p.type[i]),
                int(p.type[j]));
  return buffer;
}

// Compares every particle's list with the reference (filtered by the masks and by `radius`, which
// may be smaller than the reference's: fl(r'^2) <= fl(r^2) for r' <= r, so its pairs are a
// subset), and checks the CSR invariants: self never listed, no duplicates. Linear time (marks
// instead of sorting). Prints the first few differences with the distances that decide them, and
// their total count.
void expect_lists_equal_reference(const Particles& p, const NeighbourList& list,
                                  const Reference& reference, TypeMask query, TypeMask target,
                                  Real radius) {
  const std::uint32_t n = std::uint32_t(p.size());
  const Real r2 = radius * radius;
  ASSERT_EQ(list.offsets.size(), n + 1);
  ASSERT_EQ(list.offsets.front(), 0u);
  ASSERT_EQ(list.offsets.back(), list.indices.size());
  const Vec3* x = p.position.data();
  const ParticleType* type = p.type.data();
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> wanted(n, kNone), seen(n, kNone);  // = i: j is in i's set / list
  std::size_t missing = 0, extra = 0, self = 0, duplicates = 0, printed = 0, compared = 0;
  std::ostringstream report;
  for (std::uint32_t i = 0; i < n; ++i) {
    ASSERT_LE(list.offsets[i], list.offsets[i + 1]);
    if (in_mask(query, type[i]))
      for (std::uint32_t j : reference.of(i))
        if (in_mask(target, type[j]) && squared_norm(x[i] - x[j]) < r2) {
          wanted[j] = i;
          ++compared;
        }
    for (std::uint32_t j : list.of(i)) {
      if (j == i) {
        ++self;
        continue;
      }
      if (seen[j] == i) {
        ++duplicates;
        continue;
      }
      seen[j] = i;
      if (wanted[j] != i) {
        ++extra;
        if (printed++ < 6) report << "\n  extra   " << describe_pair(p, i, j, radius);
      }
    }
    if (in_mask(query, type[i]))
      for (std::uint32_t j : reference.of(i))
        if (wanted[j] == i && seen[j] != i) {
          ++missing;
          if (printed++ < 6) report << "\n  missing " << describe_pair(p, i, j, radius);
        }
  }
  EXPECT_EQ(self, 0u) << "entries listing a particle as its own neighbour";
  EXPECT_EQ(duplicates, 0u) << "duplicate entries in lists";
  EXPECT_EQ(missing + extra, 0u) << "query mask " << int(query) << ", target mask " << int(target)
                                 << ", radius " << radius << ": " << missing << " missing and "
                                 << extra << " extra entries (of " << compared << ")"
                                 << report.str();
  EXPECT_GT(compared, 0u) << "nothing compared: the case tests nothing";
}

NeighbourList find(const Particles& p, TypeMask query, TypeMask target, Real radius,
                   int threads = 2) {
  const CpuExecutor exec(threads);
  NeighbourGrid grid(kCellSize);
  grid.build(p, exec);
  NeighbourList list;
  grid.find_neighbours(p, query, target, radius, exec, list);
  return list;
}

// A cloud with its reference and its all-types lists (2 threads), computed once per test
// program: the sweep and the grid are the expensive parts, and several tests compare with them.
struct CloudCase {
  Particles particles;
  Reference reference;
  NeighbourList all;
  std::vector<std::uint32_t> interesting;  // extra brute-force queries
};

CloudCase make_case(Particles p, std::vector<std::uint32_t> interesting = {}) {
  CloudCase c;
  c.reference = sweep_reference(p, kCellSize);
  c.all = find(p, kAllTypes, kAllTypes, kCellSize);
  c.particles = std::move(p);
  c.interesting = std::move(interesting);
  return c;
}

const CloudCase& uniform_case() {
  static const CloudCase c = make_case(uniform_cloud());
  return c;
}
const CloudCase& clustered_case() {
  static const CloudCase c = make_case(clustered_cloud());
  return c;
}
const SparseCloud& sparse() {
  static const SparseCloud c = sparse_cloud();
  return c;
}
const CloudCase& sparse_case() {
  static const CloudCase c = [] {
    std::vector<std::uint32_t> constructed;
    for (std::uint32_t i = 0; i < sparse().constructed; i += 36) constructed.push_back(i);
    for (std::uint32_t i = 1; i < 1 + 2 * sparse().rounding_pairs; ++i) constructed.push_back(i);
    return make_case(sparse().particles, constructed);
  }();
  return c;
}

// Brute force for ~1000 queries (random ones plus the case's interesting ones) against all
// particles: the grid's lists and the sweep reference must both equal it.
void check_against_brute_force(const CloudCase& c, int random_queries) {
  const Particles& p = c.particles;
  std::vector<std::uint32_t> queries = c.interesting;
  std::mt19937 rng(404);
  std::uniform_int_distribution<std::uint32_t> pick(0, std::uint32_t(p.size() - 1));
  for (int n = 0; n < random_queries; ++n) queries.push_back(pick(rng));
  std::size_t compared = 0, grid_wrong = 0, reference_wrong = 0;
  std::ostringstream report;
  for (std::uint32_t i : queries) {
    const std::vector<std::uint32_t> want = brute_force(p, i, kCellSize);
    std::vector<std::uint32_t> got(c.all.of(i).begin(), c.all.of(i).end());
    std::sort(got.begin(), got.end());
    std::vector<std::uint32_t> ref(c.reference.of(i).begin(), c.reference.of(i).end());
    std::sort(ref.begin(), ref.end());
    compared += want.size();
    if (ref != want && reference_wrong++ == 0) report << "\n  sweep reference wrong for " << i;
    if (got != want && grid_wrong++ < 3) {
      report << "\n  grid wrong for particle " << i << ": " << got.size() << " listed, "
             << want.size() << " by brute force";
      for (std::uint32_t j : want)
        if (!std::binary_search(got.begin(), got.end(), j))
          report << "\n    missing " << describe_pair(p, i, j, kCellSize);
    }
  }
  EXPECT_EQ(reference_wrong, 0u) << report.str();
  EXPECT_EQ(grid_wrong, 0u) << "of " << queries.size() << " queries" << report.str();
  EXPECT_GT(compared, 0u);
  ::testing::Test::RecordProperty("brute_force_queries", int(queries.size()));
  ::testing::Test::RecordProperty("brute_force_pairs", int(compared));
}

// --- Against the references --------------------------------------------------------------------

TEST(NeighbourGridReference, UniformCloudMatchesSweep) {
  const CloudCase& c = uniform_case();
  ::testing::Test::RecordProperty("pairs", int(c.reference.indices.size()));
  expect_lists_equal_reference(c.particles, c.all, c.reference, kAllTypes, kAllTypes, kCellSize);
  // A radius below the cell size, liquid particles seeing frozen ones.
  const Real radius = Real(0.7) * kCellSize;
  const NeighbourList masked = find(c.particles, kLiquidMask, kFrozenMask, radius);
  expect_lists_equal_reference(c.particles, masked, c.reference, kLiquidMask, kFrozenMask, radius);
}

TEST(NeighbourGridReference, ClusteredCloudMatchesSweep) {
  const CloudCase& c = clustered_case();
  ::testing::Test::RecordProperty("pairs", int(c.reference.indices.size()));
  expect_lists_equal_reference(c.particles, c.all, c.reference, kAllTypes, kAllTypes, kCellSize);
}

TEST(NeighbourGridReference, SparseCloudMatchesSweep) {
  const CloudCase& c = sparse_case();
  ::testing::Test::RecordProperty("pairs", int(c.reference.indices.size()));
  ::testing::Test::RecordProperty("rounding_pairs", int(sparse().rounding_pairs));
  expect_lists_equal_reference(c.particles, c.all, c.reference, kAllTypes, kAllTypes, kCellSize);
}

// About 1250 queries in all (each O(N) in a Debug build: the budget of this file).
TEST(NeighbourGridReference, UniformCloudMatchesBruteForce) {
  check_against_brute_force(uniform_case(), 400);
}

TEST(NeighbourGridReference, ClusteredCloudMatchesBruteForce) {
  check_against_brute_force(clustered_case(), 400);
}

TEST(NeighbourGridReference, SparseCloudMatchesBruteForce) {
  check_against_brute_force(sparse_case(), 150);  // plus ~290 constructed particles
}

// Every mask pair and three radii on a twentieth of the clustered cloud (the mask logic does not
// depend on the cloud's size).
TEST(NeighbourGridReference, AllMaskPairsAndRadii) {
  Particles p;
  const Particles& full = clustered_case().particles;
  for (std::size_t i = 0; i < full.size(); i += 20)
    p.add(full.position[i], Vec3{}, 1, full.type[i], 0);
  const Reference reference = sweep_reference(p, kCellSize);
  const TypeMask masks[][2] = {
      {kAllTypes, kAllTypes},     {kLiquidMask, kLiquidMask},
      {kLiquidMask, kFrozenMask}, {kFrozenMask, kLiquidMask | kGranularMask},
      {kGranularMask, kAllTypes}, {kBoundaryMask, kBoundaryMask}};
  const CpuExecutor exec(2);
  NeighbourGrid grid(kCellSize);
  grid.build(p, exec);  // one build serves every query
  for (Real radius : {kCellSize, Real(0.5) * kCellSize, Real(0.999) * kCellSize})
    for (const auto& m : masks) {
      NeighbourList list;
      grid.find_neighbours(p, m[0], m[1], radius, exec, list);
      expect_lists_equal_reference(p, list, reference, m[0], m[1], radius);
    }
}

// The overload that fills several lists (one per target mask) in one scan, as the world does
// every step (liquid -> liquid, liquid -> boundary): each list equals the reference.
TEST(NeighbourGridReference, SeveralTargetListsInOneScan) {
  const CloudCase& c = clustered_case();
  const CpuExecutor exec(2);
  NeighbourGrid grid(kCellSize);
  grid.build(c.particles, exec);
  NeighbourList liquid, boundary;
  grid.find_neighbours(c.particles, kLiquidMask, {kLiquidMask, kBoundaryMask}, kCellSize, exec,
                       {&liquid, &boundary});
  expect_lists_equal_reference(c.particles, liquid, c.reference, kLiquidMask, kLiquidMask,
                               kCellSize);
  expect_lists_equal_reference(c.particles, boundary, c.reference, kLiquidMask, kBoundaryMask,
                               kCellSize);
}

// A query with kOfBodiesOnly lists the neighbours of the body particles among its types, each
// exactly as the plain query does, and nothing for the others (a static body's reactions need the
// liquid around its particles, not around every wall particle).
TEST(NeighbourGridReference, BodyOnlyQueriesListTheBodyParticlesAlone) {
  const Particles& full = clustered_case().particles;
  Particles p;
  std::size_t bodies = 0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    const bool of_a_body = full.type[i] == ParticleType::Frozen && i % 3 == 0;
    bodies += of_a_body;
    p.add(full.position[i], Vec3{}, 1, full.type[i], 0, of_a_body ? BodyId(0) : kNoBody);
  }
  ASSERT_GT(bodies, 100u);
  const NeighbourList plain = find(p, kBoundaryMask, kLiquidMask, kCellSize);
  const NeighbourList only = find(p, kBoundaryMask | kOfBodiesOnly, kLiquidMask, kCellSize);
  std::size_t listed = 0;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    const auto want = p.body[i] != kNoBody ? plain.of(i) : decltype(plain.of(i)){};
    const auto got = only.of(i);
    ASSERT_TRUE(std::equal(got.begin(), got.end(), want.begin(), want.end())) << "particle " << i;
    listed += got.size();
  }
  EXPECT_GT(listed, 100u) << "the body particles have liquid neighbours: the case tests something";
}

// --- Order and thread count --------------------------------------------------------------------

// The lists as stable ids, in id order of the query particle, each in its listed order.
std::vector<ParticleId> lists_by_id(const Particles& p, const NeighbourList& list) {
  std::vector<std::uint32_t> index_of(p.id_bound());
  for (std::uint32_t i = 0; i < p.size(); ++i) index_of[p.id[i]] = i;
  std::vector<ParticleId> out;
  out.reserve(list.total() + p.size());
  for (std::uint32_t i : index_of) {
    for (std::uint32_t j : list.of(i)) out.push_back(p.id[j]);
    out.push_back(std::numeric_limits<ParticleId>::max());  // end of a list
  }
  return out;
}

// A list depends only on positions and ids, never on where particles sit in memory
// (neighbour_grid.h): after a permutation the list of each particle, written as stable ids, is
// the same sequence, not only the same set.
enum class Reorder { Random, GridOrder };

void expect_order_independent_of_memory(const CloudCase& c, Reorder how) {
  Particles p = c.particles;
  const std::vector<ParticleId> before = lists_by_id(p, c.all);
  std::vector<std::uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0u);
  if (how == Reorder::Random) {
    std::shuffle(order.begin(), order.end(), std::mt19937(606));
  } else {
    // The grid's own locality order, as a world uses it for reordering.
    NeighbourGrid grid(kCellSize);
    grid.build(p, CpuExecutor(1));
    std::vector<std::uint32_t> sorted = grid.sorted_order();
    std::vector<std::uint32_t> check = sorted;
    std::sort(check.begin(), check.end());
    ASSERT_EQ(check, order) << "sorted_order() is not a permutation";
    ASSERT_NE(sorted, order) << "the reordering would test nothing";
    order = std::move(sorted);
  }
  p.permute(order);
  EXPECT_EQ(lists_by_id(p, find(p, kAllTypes, kAllTypes, kCellSize)), before);
}

TEST(NeighbourGridOrder, ListsIndependentOfMemoryOrderClustered) {
  expect_order_independent_of_memory(clustered_case(), Reorder::GridOrder);
}

TEST(NeighbourGridOrder, ListsIndependentOfMemoryOrderSparse) {
  // Includes coincident particles: their order within a cell comes from the ids alone.
  expect_order_independent_of_memory(sparse_case(), Reorder::Random);
}

// Determinism across thread counts (DESIGN.md, "Determinism"): the same lists, bit for bit.
TEST(NeighbourGridOrder, ListsIdenticalForOneAndTwoThreads) {
  // The clustered cloud has the most uneven work per cell (dynamic scheduling).
  const CloudCase& c = clustered_case();
  const NeighbourList one = find(c.particles, kAllTypes, kAllTypes, kCellSize, 1);
  EXPECT_EQ(one.offsets, c.all.offsets);
  EXPECT_EQ(one.indices, c.all.indices);
  EXPECT_GT(one.total(), 0u);
}

// The documented order of a list (neighbour_grid.h): the 27 cells in a fixed order (z, then y,
// then x, ascending), and a cell's targets in id order, whichever types they are. A grid that
// kept each cell's types as separate runs would have to merge them back by id for such a list.
TEST(NeighbourGridOrder, ListsRunByCellThenIdWhateverTheTypes) {
  const CloudCase& c = clustered_case();
  const Particles& p = c.particles;
  // The grid's cells: edge kCellSize from one cell below the lowest particle on every axis.
  Vec3 lo{std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max(),
          std::numeric_limits<Real>::max()};
  for (const Vec3& x : p.position)
    lo = Vec3{std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
  const Vec3 origin{lo.x - kCellSize, lo.y - kCellSize, lo.z - kCellSize};
  auto cell = [&](const Vec3& x, int a) {
    return std::int64_t(std::floor((double(x[a]) - double(origin[a])) / double(kCellSize)));
  };
  auto order_key = [&](std::uint32_t j) {
    const Vec3& x = p.position[j];
    return std::array<std::int64_t, 4>{cell(x, 2), cell(x, 1), cell(x, 0), std::int64_t(p.id[j])};
  };
  for (TypeMask target : {kAllTypes, TypeMask(kLiquidMask | kFrozenMask), kLiquidMask}) {
    const NeighbourList list = find(p, kAllTypes, target, kCellSize);
    std::size_t pairs = 0, mixed = 0, out_of_order = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      const std::uint32_t* of = list.of(i).first;
      for (std::size_t k = 1; k < list.of(i).size(); ++k) {
        ++pairs;
        mixed += p.type[of[k - 1]] != p.type[of[k]];
        out_of_order += !(order_key(of[k - 1]) < order_key(of[k]));
      }
    }
    EXPECT_EQ(out_of_order, 0u) << "target mask " << int(target) << ": " << out_of_order << " of "
                                << pairs << " consecutive entries out of order";
    if (target != kLiquidMask) {
      EXPECT_GT(mixed, pairs / 10) << "the case mixes too few types to test the merge";
    }
  }
}

// --- Small cases -------------------------------------------------------------------------------

TEST(NeighbourGridEdgeCases, EmptyAndSingleParticle) {
  Particles p;
  NeighbourList list = find(p, kAllTypes, kAllTypes, kCellSize);
  EXPECT_EQ(list.offsets, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(list.indices.empty());
  p.add(Vec3{1, 2, 3}, Vec3{}, 1, ParticleType::Liquid, 0);
  list = find(p, kAllTypes, kAllTypes, kCellSize);
  EXPECT_EQ(list.offsets, (std::vector<std::uint32_t>{0, 0}));
  EXPECT_TRUE(list.indices.empty());
}

// Five particles, lists worked out by hand.
TEST(NeighbourGridEdgeCases, SmallHandCheckedCase) {
  Particles p;
  p.add(Vec3{0, 0, 0}, Vec3{}, 1, ParticleType::Liquid, 0);
  p.add(Vec3{Real(0.05), 0, 0}, Vec3{}, 1, ParticleType::Frozen, 0);
  p.add(Vec3{Real(0.25), 0, 0}, Vec3{}, 1, ParticleType::Liquid, 0);
  p.add(Vec3{0, Real(0.09), 0}, Vec3{}, 1, ParticleType::Liquid, 0);
  p.add(Vec3{0, 0, -kCellSize}, Vec3{}, 1, ParticleType::Liquid, 0);
  auto sorted = [](IndexRange r) {
    std::vector<std::uint32_t> v(r.begin(), r.end());
    std::sort(v.begin(), v.end());
    return v;
  };
  using V = std::vector<std::uint32_t>;
  // |x0 - x1| = 0.05, |x0 - x3| = 0.09, |x1 - x3| = sqrt(0.05^2 + 0.09^2) = 0.103 > 0.1,
  // |x1 - x2| = 0.2, and |x0 - x4| = 0.1 exactly: not a neighbour (the test is r < radius).
  const NeighbourList all = find(p, kAllTypes, kAllTypes, kCellSize);
  EXPECT_EQ(sorted(all.of(0)), (V{1, 3}));
  EXPECT_EQ(sorted(all.of(1)), (V{0}));
  EXPECT_EQ(sorted(all.of(2)), (V{}));
  EXPECT_EQ(sorted(all.of(3)), (V{0}));
  EXPECT_EQ(sorted(all.of(4)), (V{}));
  const NeighbourList liquid_to_frozen = find(p, kLiquidMask, kFrozenMask, kCellSize);
  EXPECT_EQ(sorted(liquid_to_frozen.of(0)), (V{1}));
  EXPECT_EQ(sorted(liquid_to_frozen.of(1)), (V{}));  // frozen: not a query particle
  EXPECT_EQ(sorted(liquid_to_frozen.of(3)), (V{}));
}

}  // namespace
}  // namespace upf
