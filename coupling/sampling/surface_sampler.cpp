#include "coupling/sampling/surface_sampler.h"

#include <algorithm>
#include <cmath>

#include "coupling/mesh/mesh_error.h"
#include "coupling/mesh/mesh_validation.h"
#include "coupling/sampling/dart_throwing.h"
#include "coupling/sampling/gap_filling.h"

namespace upf {

namespace {

// Refuse spacings that would give more than this many spacing-squares of area (~3e7 samples).
constexpr double kMaxAreaInSpacings = 1e7;
// Cells per axis the grid can address with room to spare (cell_of() converts to int64).
constexpr double kMaxExtentInSpacings = 1e15;

void require_samplable(const TriangleMesh& mesh, const SurfaceSamplingOptions& options,
                       const std::string& where) {
  const double spacing = options.spacing;
  if (!std::isfinite(spacing) || !(spacing > 0))
    throw mesh_error(
        mesh.source, where,
        "the sampling spacing must be finite and positive, got " + format_number(spacing) + " m");
  if (!(options.dart_radius >= kSampleMinDistance && options.dart_radius <= 10) ||
      !(options.darts_per_disk >= 0 && options.darts_per_disk <= 1000))
    throw mesh_error(mesh.source, where,
                     "sampling tuning out of range: dart radius in [0.45, 10] spacings, darts per "
                     "disk in [0, 1000]");
  require_usable_surface(mesh, where);
  const double area = surface_area(mesh);
  const Eigen::AlignedBox3d box = bounding_box(mesh);
  const double farthest =
      box.isEmpty() ? 0 : box.min().cwiseAbs().cwiseMax(box.max().cwiseAbs()).maxCoeff();
  if (!(area / (spacing * spacing) <= kMaxAreaInSpacings) ||
      !(farthest / spacing <= kMaxExtentInSpacings))
    throw mesh_error(mesh.source, where,
                     "spacing " + format_number(spacing) + " m is too fine for this mesh (area " +
                         format_number(area) + " m^2, " + format_number(farthest) +
                         " m from the origin); check the spacing and the mesh's units");
}

}  // namespace

SurfaceSamples sample_surface(const TriangleMesh& mesh, const SurfaceSamplingOptions& options,
                              const std::string& where) {
  require_samplable(mesh, options, where);
  const double coverage = kSampleCoverageRadius * options.spacing;
  const double dart_radius = options.dart_radius * options.spacing;
  SampleSet samples(mesh, 2 * std::max(coverage, dart_radius));
  throw_darts(mesh, dart_radius, options.darts_per_disk, options.seed, samples);
  fill_gaps(mesh, coverage, kSampleMinDistance * options.spacing, samples);
  return samples.take();
}

}  // namespace upf
