// Anisotropic smoothing kernels for the liquid surface: the method of Yu & Turk 2013,
// "Reconstructing surfaces of particle-based fluids using anisotropic kernels", ACM TOG 32(1).
//
// Each liquid particle gets an ellipsoidal kernel shaped by the spread of its neighbours:
//   1. the weighted mean m_i and covariance C_i of the neighbours within r = neighbourhood * h,
//      with weights w = 1 - (d / r)^3 (their Eqs. 5-7);
//   2. C_i = R diag(s1, s2, s3) R^T (s1 >= s2 >= s3); the stretches are the eigenvalues over
//      those of a full neighbourhood (a particle deep in the liquid gets 1, 1, 1), at most 1, and
//      no smaller than s1 / max_stretch, so a kernel is at most max_stretch times thinner in one
//      direction than in another (their k_r; Eq. 15). A particle with fewer than min_neighbours
//      neighbours gets sparse_scale in every direction (their N_epsilon and k_n): spray stays
//      round drops;
//   3. the stretches are scaled to a product of 1, so every kernel keeps the volume of the round
//      one and only changes shape (not in Yu & Turk, whose kernels shrink with the spread: a
//      resting pool's face then sank 0.10 h and a box lost 4.8 % of its volume, against 0.05 h
//      and 1.6 % with this; tests/unit/test_surface_smoothness.cpp, docs/rendering.md);
//      G_i = R diag(1 / stretch) R^T / (kernel_radius * h), and the kernel
//      W_i(x) = h^3 det(G_i) P(|G_i (x - c_i)|) with P the Wendland C2 kernel of support 1 (their
//      Eq. 12 with Wendland's P). Its integral is h^3, the volume a particle stands for, so the
//      sum over a resting lattice is 1 inside and 1/2 on a flat face h/2 beyond the outer
//      centres: the surface is the level 1/2 of the sum;
//   5. the centre c_i = (1 - centre_smoothing) x_i + centre_smoothing m_i (their Laplacian
//      smoothing, Eq. 6; off by default, see LiquidSurfaceOptions).
// Near a flat surface a particle's neighbours spread less across the surface than along it, so
// its kernel flattens into a disc: the surface no longer shows a bump per particle, and a thin
// sheet (neighbours in a plane) stays a sheet. Deep in the liquid the kernels stay spheres.
//
// No OpenVDB here: liquid_surface.cpp samples the field on its grid.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace upf {

// Lengths in units of the particle spacing h.
struct AnisotropyParameters {
  double neighbourhood = 4.0;     // r / h, the radius of the covariance (Yu & Turk: 2 h_SPH)
  double kernel_radius = 2.5;     // support of an undeformed kernel / h
  double max_stretch = 4.0;       // k_r: largest ratio of a kernel's axes
  int min_neighbours = 25;        // N_epsilon: fewer neighbours make a round kernel
  double sparse_scale = 0.5;      // k_n: the stretch of such a round kernel
  double centre_smoothing = 0.0;  // lambda in [0, 1]
  double level = 0.5;             // the surface is where the kernel sum equals this
};

struct AnisotropicKernel {
  Eigen::Vector3d centre;
  Eigen::Matrix3d g;       // G_i: maps an offset from the centre to the kernel's unit ball
  double amplitude;        // h^3 det(G_i); W_i = amplitude wendland_3d(q, 1)
  Eigen::Vector3d extent;  // half-sizes of the support's bounding box about the centre
};

// One kernel per position (same order). h > 0; the parameters must be in range (checked by the
// caller, liquid_surface.cpp). The result does not depend on the number of threads.
std::vector<AnisotropicKernel> anisotropic_kernels(const std::vector<Eigen::Vector3d>& positions,
                                                   double h, const AnisotropyParameters& p);

// Points bucketed into cubic cells, each cell's points in input order.
class CellBuckets {
 public:
  using Cell = std::array<std::int64_t, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  CellBuckets(const std::vector<Eigen::Vector3d>& points, double cell_size);
  // Each box (centres and half-sizes) in every cell it overlaps.
  CellBuckets(const std::vector<Eigen::Vector3d>& centres,
              const std::vector<Eigen::Vector3d>& half_sizes, double cell_size);
  Cell cell_of(const Eigen::Vector3d& x) const;
  // The points of `cell` (empty if none).
  const std::vector<std::uint32_t>& at(const Cell& cell) const;

 private:
  double cell_size_;
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells_;
  std::vector<std::uint32_t> none_;
};

// The sum of the kernels, sum_i W_i(x): about 1 inside the liquid, 1/2 on its surface, 0 outside.
// Holds references to `kernels`, which must outlive it. Thread-safe to query.
class KernelField {
 public:
  // `cell_size`: the side of the cells that index the kernels (about a kernel's support).
  KernelField(const std::vector<AnisotropicKernel>& kernels, double cell_size);
  double operator()(const Eigen::Vector3d& x) const;

 private:
  const std::vector<AnisotropicKernel>& kernels_;
  // Every kernel in each cell its support's box overlaps: a point sees only the kernels of its
  // own cell, summed in a fixed order (the kernels' order).
  CellBuckets buckets_;
};

}  // namespace upf
