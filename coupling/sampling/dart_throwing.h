// Dart throwing on a triangle mesh: uniform random points, area-proportional per triangle, each
// kept when no sample lies within `radius` (R. L. Cook 1986, "Stochastic sampling in computer
// graphics", ACM TOG 5(1); on meshes as in M. Corsini, P. Cignoni, R. Scopigno 2012, "Efficient
// and flexible sampling with blue noise properties of triangular meshes", IEEE TVCG 18(6)).
//
// Random numbers: std::mt19937_64 (its output is fixed by the C++ standard) turned into doubles
// with explicit arithmetic, not std::uniform_real_distribution (implementation-defined), and the
// triangles are visited in order: the same darts on every platform and run.
#pragma once

#include <cstdint>

#include "coupling/mesh/triangle_mesh.h"
#include "coupling/sampling/sample_set.h"

namespace upf {

// Throws darts_per_disk darts per pi radius^2 of area (fractions rounded stochastically per
// triangle). Triangles of zero area get none.
void throw_darts(const TriangleMesh& mesh, double radius, double darts_per_disk, std::uint64_t seed,
                 SampleSet& samples);

}  // namespace upf
