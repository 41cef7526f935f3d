// Volume, centre of mass and inertia tensor of a closed triangle mesh of uniform density.
//
// Method: the divergence theorem turns each volume integral (1, x, y, z, x^2, y^2, z^2, xy, yz,
// zx) into a sum over the triangles of closed-form polynomial terms: B. Mirtich 1996, "Fast and
// accurate computation of polyhedral mass properties", J. Graphics Tools 1(2); in the compact
// form of D. Eberly 2002, "Polyhedral Mass Properties (Revisited)", Geometric Tools. Exact for
// the polyhedron up to rounding. Vertices are taken relative to the bounding box centre first, so
// a mesh far from the origin loses no digits to cancellation.
#pragma once

#include <Eigen/Core>
#include <string>

#include "coupling/mesh/triangle_mesh.h"

namespace upf {

struct MassProperties {
  double volume = 0;                                         // m^3, positive
  double mass = 0;                                           // kg
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  // m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();         // kg m^2, about the centre of mass,
                                                             // world axes
};

// Positive when the triangles' normals point out of the enclosed volume, negative when every
// one points in. Meaningful for closed meshes only.
double signed_volume(const TriangleMesh& mesh);

// Reverses every winding when the mesh is inside out (negative signed volume), so that triangle
// normals, and the normals of surface samples, point outwards. Returns whether it flipped.
bool orient_outward(TriangleMesh& mesh);

// Mass properties at `density` (kg/m^3). An inside-out mesh (consistently inward-facing) gives
// the same result as its flipped copy: orientation is a property of the file, not of the body.
// Throws InputError at `where` naming mesh.source when the mesh is not closed (require_closed),
// encloses no volume, or density is not finite and positive.
MassProperties mass_properties(const TriangleMesh& mesh, double density, const std::string& where);

}  // namespace upf
