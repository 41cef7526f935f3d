// Gap filling: completes a sample set so that every point of the mesh's surface lies within
// `coverage` of a sample, adding only samples at least `min_distance` from all others
// (min_distance < coverage). Recursive subdivision of the triangles, after M. S. Ebeida et al.
// 2011, "Efficient maximal Poisson-disk sampling", ACM TOG 30(4), on triangles instead of
// squares:
//
//  - a (sub-)triangle inside one sample's ball of radius `coverage` is covered (a ball is convex:
//    holding the three corners, it holds the triangle);
//  - a triangle whose points all lie within reach <= coverage - min_distance of its centroid is
//    a leaf: if a sample lies within coverage - reach of the centroid, every point of the leaf is
//    within coverage of it; otherwise the nearest sample is farther than coverage - reach >=
//    min_distance, and the centroid becomes a sample, within reach < coverage of every point;
//  - any other triangle is split into four at its edge midpoints (depth first, a fixed order).
#pragma once

#include "coupling/mesh/triangle_mesh.h"
#include "coupling/sampling/sample_set.h"

namespace upf {

// Triangles of zero area are skipped: their points lie on their neighbours' edges.
void fill_gaps(const TriangleMesh& mesh, double coverage, double min_distance, SampleSet& samples);

}  // namespace upf
