// The samples taken so far on a mesh: what the sampler returns, plus the grid that answers
// "is a sample near here?" while sampling.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "coupling/mesh/triangle_mesh.h"
#include "coupling/sampling/sample_grid.h"

namespace upf {

struct SurfaceSamples {
  std::vector<Eigen::Vector3d> positions;
  // Unit normal of the triangle under each sample, by its winding: outward for a closed mesh
  // after orient_outward().
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::uint32_t> triangles;  // the triangle each sample lies on
};

class SampleSet {
 public:
  // `cell_size`: twice the usual query radius keeps queries to 2 x 2 x 2 cells.
  SampleSet(const TriangleMesh& mesh, double cell_size) : mesh_(mesh), grid_(cell_size) {}

  // Adds a sample at p on triangle t (which must have non-zero area: its normal is taken).
  void add(const Eigen::Vector3d& p, std::uint32_t t);
  const SampleGrid& grid() const { return grid_; }
  SurfaceSamples take() { return std::move(samples_); }

 private:
  const TriangleMesh& mesh_;
  SampleGrid grid_;
  SurfaceSamples samples_;
};

}  // namespace upf
