#include "coupling/mesh/mass_properties.h"

#include <array>
#include <cmath>

#include "coupling/mesh/closed_mesh.h"
#include "coupling/mesh/mesh_error.h"

namespace upf {

namespace {

// Volume integrals of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx (Eberly 2002, "Polyhedral Mass
// Properties (Revisited)", function Compute).
using VolumeIntegrals = std::array<double, 10>;

// Eberly's per-axis subexpressions of one triangle's coordinates w0, w1, w2.
struct Subexpressions {
  double f1, f2, f3, g0, g1, g2;
};
Subexpressions subexpressions(double w0, double w1, double w2) {
  const double temp0 = w0 + w1;
  const double temp1 = w0 * w0;
  const double temp2 = temp1 + w1 * temp0;
  Subexpressions s{};
  s.f1 = temp0 + w2;
  s.f2 = temp2 + w2 * s.f1;
  s.f3 = w0 * temp1 + w1 * temp2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

// Integrals over the volume, vertices taken relative to `origin`.
VolumeIntegrals volume_integrals(const TriangleMesh& mesh, const Eigen::Vector3d& origin) {
  VolumeIntegrals sum{};
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d p0 = mesh.vertices[t[0]] - origin;
    const Eigen::Vector3d p1 = mesh.vertices[t[1]] - origin;
    const Eigen::Vector3d p2 = mesh.vertices[t[2]] - origin;
    const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);  // twice the area, outward normal
    const Subexpressions x = subexpressions(p0.x(), p1.x(), p2.x());
    const Subexpressions y = subexpressions(p0.y(), p1.y(), p2.y());
    const Subexpressions z = subexpressions(p0.z(), p1.z(), p2.z());
    sum[0] += d.x() * x.f1;
    sum[1] += d.x() * x.f2;
    sum[2] += d.y() * y.f2;
    sum[3] += d.z() * z.f2;
    sum[4] += d.x() * x.f3;
    sum[5] += d.y() * y.f3;
    sum[6] += d.z() * z.f3;
    sum[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
    sum[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
    sum[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
  }
  constexpr VolumeIntegrals kFactors = {1.0 / 6,  1.0 / 24, 1.0 / 24,  1.0 / 24,  1.0 / 60,
                                        1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] *= kFactors[i];
  return sum;
}

Eigen::Vector3d reference_point(const TriangleMesh& mesh) {
  if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
  return bounding_box(mesh).center();
}

}  // namespace

double signed_volume(const TriangleMesh& mesh) {
  return volume_integrals(mesh, reference_point(mesh))[0];
}

bool orient_outward(TriangleMesh& mesh) {
  if (signed_volume(mesh) >= 0) return false;
  flip_winding(mesh);
  return true;
}

MassProperties mass_properties(const TriangleMesh& mesh, double density, const std::string& where) {
  if (!std::isfinite(density) || !(density > 0))
    throw mesh_error(
        mesh.source, where,
        "density must be finite and positive, got " + format_number(density) + " kg/m^3");
  require_closed(mesh, where);
  const Eigen::Vector3d origin = reference_point(mesh);
  VolumeIntegrals integral = volume_integrals(mesh, origin);
  // Inside out: every integral changes sign, exactly as flipping every winding would undo.
  if (integral[0] < 0)
    for (double& value : integral) value = -value;
  const double scale = bounding_box(mesh).diagonal().norm();
  // Below this the volume is rounding noise: a flat, closed shell (two faces back to back).
  if (!(integral[0] > 1e-12 * scale * scale * scale))
    throw mesh_error(mesh.source, where, "encloses no volume (it is flat)");

  MassProperties out;
  out.volume = integral[0];
  out.mass = density * out.volume;
  const Eigen::Vector3d c(integral[1] / integral[0], integral[2] / integral[0],
                          integral[3] / integral[0]);
  // Second moments about the centre of mass (parallel axis theorem), per unit density.
  const double xx = integral[4] - integral[0] * c.x() * c.x();
  const double yy = integral[5] - integral[0] * c.y() * c.y();
  const double zz = integral[6] - integral[0] * c.z() * c.z();
  const double xy = integral[7] - integral[0] * c.x() * c.y();
  const double yz = integral[8] - integral[0] * c.y() * c.z();
  const double zx = integral[9] - integral[0] * c.z() * c.x();
  out.inertia << yy + zz, -xy, -zx,  //
      -xy, zz + xx, -yz,             //
      -zx, -yz, xx + yy;
  out.inertia *= density;
  out.center_of_mass = origin + c;
  return out;
}

}  // namespace upf
