// Yu & Turk 2013 anisotropic kernels (see anisotropic_kernels.h).
#include "framework/output/anisotropic_kernels.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "framework/core/wendland.h"

namespace upf {

namespace {

double covariance_weight(double distance, double radius) {
  const double x = distance / radius;
  return 1 - x * x * x;
}

// The per-axis variance of a full neighbourhood: lattice points of unit spacing around a lattice
// point, weighted as the covariance weights them, over a radius of `radius` spacings. A
// particle deep in resting liquid has this variance in every direction, so its stretches are 1.
double full_neighbourhood_variance(double radius) {
  const int n = int(std::ceil(radius));
  double sum_w = 0;
  double sum_wx2 = 0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        const double d = std::sqrt(double(i * i + j * j + k * k));
        if (d >= radius) continue;
        const double w = covariance_weight(d, radius);
        sum_w += w;
        sum_wx2 += w * i * i;
      }
  return sum_wx2 / sum_w;
}

}  // namespace

std::size_t CellBuckets::CellHash::operator()(const Cell& c) const {
  // Large odd multipliers mix the three coordinates (Teschner et al. 2003, spatial hashing).
  const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
  return static_cast<std::size_t>(u(c[0]) * 73856093ULL ^ u(c[1]) * 19349663ULL ^
                                  u(c[2]) * 83492791ULL);
}

CellBuckets::CellBuckets(const std::vector<Eigen::Vector3d>& points, double cell_size)
    : cell_size_(cell_size) {
  for (std::size_t i = 0; i < points.size(); ++i)
    cells_[cell_of(points[i])].push_back(static_cast<std::uint32_t>(i));
}

CellBuckets::CellBuckets(const std::vector<Eigen::Vector3d>& centres,
                         const std::vector<Eigen::Vector3d>& half_sizes, double cell_size)
    : cell_size_(cell_size) {
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Cell lo = cell_of(centres[i] - half_sizes[i]);
    const Cell hi = cell_of(centres[i] + half_sizes[i]);
    for (std::int64_t a = lo[0]; a <= hi[0]; ++a)
      for (std::int64_t b = lo[1]; b <= hi[1]; ++b)
        for (std::int64_t c = lo[2]; c <= hi[2]; ++c)
          cells_[{a, b, c}].push_back(static_cast<std::uint32_t>(i));
  }
}

CellBuckets::Cell CellBuckets::cell_of(const Eigen::Vector3d& x) const {
  return {static_cast<std::int64_t>(std::floor(x.x() / cell_size_)),
          static_cast<std::int64_t>(std::floor(x.y() / cell_size_)),
          static_cast<std::int64_t>(std::floor(x.z() / cell_size_))};
}

const std::vector<std::uint32_t>& CellBuckets::at(const Cell& cell) const {
  const auto found = cells_.find(cell);
  return found == cells_.end() ? none_ : found->second;
}

std::vector<AnisotropicKernel> anisotropic_kernels(const std::vector<Eigen::Vector3d>& positions,
                                                   double h, const AnisotropyParameters& p) {
  const double radius = p.neighbourhood * h;
  const double support = p.kernel_radius * h;
  const double reference_variance = full_neighbourhood_variance(p.neighbourhood) * h * h;
  const CellBuckets buckets(positions, radius);
  std::vector<AnisotropicKernel> kernels(positions.size());

  const auto kernel_of = [&](std::size_t i) {
    const Eigen::Vector3d& xi = positions[i];
    const CellBuckets::Cell home = buckets.cell_of(xi);
    // Weighted mean and neighbour count (the particle itself has weight 1, as in Yu & Turk).
    double sum_w = 0;
    Eigen::Vector3d sum_wx = Eigen::Vector3d::Zero();
    int neighbours = 0;
    const auto for_each_neighbour = [&](auto&& visit) {
      for (std::int64_t a = -1; a <= 1; ++a)
        for (std::int64_t b = -1; b <= 1; ++b)
          for (std::int64_t c = -1; c <= 1; ++c)
            for (std::uint32_t j : buckets.at({home[0] + a, home[1] + b, home[2] + c})) {
              const double d = (positions[j] - xi).norm();
              if (d < radius) visit(j, covariance_weight(d, radius));
            }
    };
    for_each_neighbour([&](std::uint32_t j, double w) {
      sum_w += w;
      sum_wx += w * positions[j];
      if (j != i) ++neighbours;
    });
    const Eigen::Vector3d mean = sum_wx / sum_w;

    AnisotropicKernel& k = kernels[i];
    k.centre = (1 - p.centre_smoothing) * xi + p.centre_smoothing * mean;
    Eigen::Vector3d stretch = Eigen::Vector3d::Constant(p.sparse_scale);
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    if (neighbours >= p.min_neighbours) {
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for_each_neighbour([&](std::uint32_t j, double w) {
        const Eigen::Vector3d d = positions[j] - mean;
        covariance += w * d * d.transpose();
      });
      covariance /= sum_w;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
      const Eigen::Vector3d s = (eigen.eigenvalues() / reference_variance).cwiseMin(1.0);
      const double largest = s.maxCoeff();
      if (largest > 1e-6) {  // otherwise all neighbours sit on one point: keep a round kernel
        stretch = s.cwiseMax(largest / p.max_stretch);
        stretch /= std::cbrt(stretch.prod());
        axes = eigen.eigenvectors();
      }
    }
    k.g = axes * stretch.cwiseInverse().asDiagonal() * axes.transpose() / support;
    const double det = 1.0 / (support * support * support * stretch.prod());
    k.amplitude = h * h * h * det;
    // The support is the ellipsoid A B with A = G^-1 and B the unit ball; its extent along
    // world axis e is the length of row e of A.
    const Eigen::Matrix3d a = axes * (support * stretch).asDiagonal() * axes.transpose();
    k.extent = a.rowwise().norm();
  };

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, positions.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) kernel_of(i);
                    });
  return kernels;
}

namespace {

std::vector<Eigen::Vector3d> centres_of(const std::vector<AnisotropicKernel>& kernels) {
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(kernels.size());
  for (const auto& k : kernels) centres.push_back(k.centre);
  return centres;
}

std::vector<Eigen::Vector3d> extents_of(const std::vector<AnisotropicKernel>& kernels) {
  std::vector<Eigen::Vector3d> extents;
  extents.reserve(kernels.size());
  for (const auto& k : kernels) extents.push_back(k.extent);
  return extents;
}

}  // namespace

KernelField::KernelField(const std::vector<AnisotropicKernel>& kernels, double cell_size)
    : kernels_(kernels), buckets_(centres_of(kernels), extents_of(kernels), cell_size) {}

double KernelField::operator()(const Eigen::Vector3d& x) const {
  double sum = 0;
  for (std::uint32_t j : buckets_.at(buckets_.cell_of(x))) {
    const AnisotropicKernel& k = kernels_[j];
    const Eigen::Vector3d d = x - k.centre;
    if ((d.cwiseAbs().array() >= k.extent.array()).any()) continue;
    const double q = (k.g * d).norm();
    sum += k.amplitude * wendland_3d(q, 1.0);
  }
  return sum;
}

}  // namespace upf
