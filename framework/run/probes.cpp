#include "framework/run/probes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/wendland.h"

namespace upf {

namespace {
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
