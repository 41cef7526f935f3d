// Samples a triangle mesh's surface into boundary points at spacing h, with two guarantees that
// hold by construction (up to rounding), for any mesh:
//
//   coverage: every point of the surface lies within h/2 of a sample, so no gap on the surface
//             (no sample-free disk) is wider than h;
//   spacing:  no two samples are closer than 0.45 h.
//
// Method: a maximal Poisson-disk sampling of the surface in two phases.
// 1. Dart throwing (R. L. Cook 1986, "Stochastic sampling in computer graphics", ACM TOG 5(1);
//    on meshes as in M. Corsini, P. Cignoni, R. Scopigno 2012, "Efficient and flexible sampling
//    with blue noise properties of triangular meshes", IEEE TVCG 18(6)): uniform random points,
//    area-proportional per triangle, each kept when no sample lies within the dart radius
//    (h/2 by default). This places most samples; the darts alone leave small holes.
// 2. Gap filling by recursive subdivision (M. S. Ebeida et al. 2011, "Efficient maximal
//    Poisson-disk sampling", ACM TOG 30(4), on triangles instead of squares): a sub-triangle
//    inside one sample's h/2 ball is covered; one small enough that its points are within
//    (h/2 - 0.45 h) of its centroid gets the centroid as a sample unless a sample already lies
//    close enough to cover it; any other is split into four at its edge midpoints.
// Random numbers come from std::mt19937_64 with explicit arithmetic (no std distributions, whose
// output differs between standard libraries) and the work is sequential, so one mesh and one
// spacing give the same samples on every run, thread count and standard library.
#pragma once

#include <cstdint>
#include <string>

#include "coupling/mesh/triangle_mesh.h"
#include "coupling/sampling/sample_set.h"

namespace upf {

// Every surface point is within this many spacings of a sample.
inline constexpr double kSampleCoverageRadius = 0.5;
// No two samples are closer than this many spacings.
inline constexpr double kSampleMinDistance = 0.45;

struct SurfaceSamplingOptions {
  double spacing = 0;      // h, m: usually the particle spacing
  std::uint64_t seed = 1;  // a fixed seed: the same samples on every run
  // Tuning only: the guarantees hold for any values in range (checked); they change the count
  // and the cost (docs/meshes.md has the measurements).
  double dart_radius = 0.5;     // in spacings, >= kSampleMinDistance
  double darts_per_disk = 8.0;  // darts per pi dart_radius^2 of area
};

// Throws InputError at `where` naming mesh.source when the spacing is not finite and positive,
// or so small for the mesh that the samples would not fit in memory, or the mesh fails
// require_usable_surface(). Triangles of zero area are
// skipped (their points lie on their neighbours' edges).
SurfaceSamples sample_surface(const TriangleMesh& mesh, const SurfaceSamplingOptions& options,
                              const std::string& where);

}  // namespace upf
