#include "solvers/sources/outflow_buffer.h"

#include <algorithm>
#include <cmath>

#include "framework/executors/rank_collectives.h"
#include "framework/particles/particles.h"

namespace upf {

namespace {

// Speeds are summed as integers of 2^-24 m/s: exact and order-free, so every thread and rank
// count gets the same mean (1e4 m/s times 5e7 particles still fits).
constexpr double kSpeedUnit = 16777216.0;

}  // namespace

OutflowBuffer::OutflowBuffer(OutflowBufferDesc desc)
    : desc_(desc), sums_(2 * std::size_t(desc.cells[0]) * std::size_t(desc.cells[1]), 0) {}

double OutflowBuffer::along(const Vec3& x) const {
  return desc_.sign * (double(x[desc_.axis]) - desc_.face);
}

std::optional<std::size_t> OutflowBuffer::cell_of(const Vec3& x) const {
  std::size_t index = 0;
  for (int k = 0; k < 2; ++k) {
    const double c = std::floor((double(x[desc_.across[k]]) - desc_.lo[k]) / desc_.cell[k]);
    if (!(c >= 0 && c < double(desc_.cells[k]))) return std::nullopt;
    index = index * std::size_t(desc_.cells[k]) + std::size_t(c);
  }
  return index;
}

void OutflowBuffer::apply(Particles& particles, const RankCollectives* ranks) {
  const std::size_t cells = sums_.size() / 2;
  if (!desc_.speed) {
    std::fill(sums_.begin(), sums_.end(), 0);
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (particles.type[i] != ParticleType::Liquid) continue;
      const double d = along(particles.position[i]);
      if (d < -desc_.length - desc_.reference || d >= -desc_.length) continue;
      const auto c = cell_of(particles.position[i]);
      if (!c) continue;
      sums_[*c] +=
          std::llround(desc_.sign * double(particles.velocity[i][desc_.axis]) * kSpeedUnit);
      sums_[cells + *c] += 1;
    }
    if (ranks) ranks->sum(sums_.data(), sums_.size());
  }
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.type[i] != ParticleType::Liquid) continue;
    const double d = along(particles.position[i]);
    if (d < -desc_.length || d >= 0) continue;
    const auto c = cell_of(particles.position[i]);
    if (!c) continue;
    double speed = 0;
    if (desc_.speed) {
      speed = *desc_.speed;
    } else {
      if (sums_[cells + *c] == 0) continue;  // nothing arrives here: left as it is
      speed = std::max(0.0, double(sums_[*c]) / kSpeedUnit / double(sums_[cells + *c]));
    }
    particles.velocity[i][desc_.axis] = Real(desc_.sign * speed);
  }
}

}  // namespace upf
