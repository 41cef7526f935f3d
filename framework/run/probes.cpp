#include "framework/run/probes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace upf {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Wendland C2 kernels of support radius r at distance d (Wendland 1995; the normalisations of
// Dehnen & Aly 2012): each integrates to one over the plane (2D) or space (3D).
double wendland_2d(double d, double r) {
  const double q = d / r;
  if (q >= 1) return 0;
  const double a = 1 - q;
  return 7 / (kPi * r * r) * a * a * a * a * (1 + 4 * q);
}
double wendland_3d(double d, double r) {
  const double q = d / r;
  if (q >= 1) return 0;
  const double a = 1 - q;
  return 21 / (2 * kPi * r * r * r) * a * a * a * a * (1 + 4 * q);
}

bool inside(const Box& box, const Vec3& x) {
  for (int a = 0; a < 3; ++a)
    if (double(x[a]) < box.min[a] || double(x[a]) > box.max[a]) return false;
  return true;
}
}  // namespace

const char* probe_unit(ProbeKind kind) {
  return kind == ProbeKind::Pressure ? "Pa" : "m";
}

double evaluate_probe(const ProbeDesc& probe, const Particles& particles, Real spacing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = particles.size();
  switch (probe.kind) {
    case ProbeKind::Extent: {
      double best = nan;
      for (std::size_t i = 0; i < n; ++i) {
        if (particles.type[i] != ParticleType::Liquid) continue;
        const Vec3& x = particles.position[i];
        if (probe.region && !inside(*probe.region, x)) continue;
        const double c = double(x[probe.axis]);
        if (std::isnan(best) || (probe.max_side ? c > best : c < best)) best = c;
      }
      if (!probe.surface || std::isnan(best)) return best;
      return best + (probe.max_side ? 0.5 : -0.5) * double(spacing);
    }
    case ProbeKind::Height: {
      const int u = (probe.axis + 1) % 3, w = (probe.axis + 2) % 3;
      // `at` lists the other two coordinates in axis order.
      const int first = std::min(u, w), second = std::max(u, w);
      double top = nan, depth = 0;
      const double r2 = probe.radius * probe.radius;
      // Each liquid particle stands for the volume s^3 (its mass is rho0 s^3).
      const double volume = double(spacing) * double(spacing) * double(spacing);
      for (std::size_t i = 0; i < n; ++i) {
        if (particles.type[i] != ParticleType::Liquid) continue;
        const Vec3& x = particles.position[i];
        const double d0 = double(x[first]) - probe.at[0], d1 = double(x[second]) - probe.at[1];
        const double d2 = d0 * d0 + d1 * d1;
        if (d2 > r2) continue;
        const double c = double(x[probe.axis]);
        if (std::isnan(top) || c > top) top = c;
        if (probe.method == ProbeMethod::Volume)
          depth += volume * wendland_2d(std::sqrt(d2), probe.radius);
      }
      // A dry wave gauge reads zero depth; a dry column has no surface to report.
      if (probe.method == ProbeMethod::Volume) return depth;
      return std::isnan(top) ? nan : top + 0.5 * double(spacing);
    }
    case ProbeKind::Pressure: {
      const std::vector<Real>* pressure = particles.find_scalar("pressure");
      if (!pressure) return nan;
      const bool kernel = probe.method == ProbeMethod::Kernel;
      double sum = 0, weights = 0;
      const double r2 = probe.radius * probe.radius;
      for (std::size_t i = 0; i < n; ++i) {
        if (particles.type[i] != ParticleType::Liquid) continue;
        const Vec3& x = particles.position[i];
        const Eigen::Vector3d d(double(x.x) - probe.center[0], double(x.y) - probe.center[1],
                                double(x.z) - probe.center[2]);
        if (d.squaredNorm() > r2) continue;
        // Liquid particles share one volume, so it cancels from the Shepard normalisation.
        const double weight = kernel ? wendland_3d(d.norm(), probe.radius) : 1.0;
        sum += weight * double((*pressure)[i]);
        weights += weight;
      }
      return weights > 0 ? sum / weights : nan;
    }
  }
  return nan;
}

}  // namespace upf
