#include "solvers/sources/speed_profile.h"

#include <algorithm>
#include <stdexcept>

namespace upf {

SpeedProfile::SpeedProfile(std::vector<std::pair<double, double>> keyframes, double start,
                           double end)
    : keyframes_(std::move(keyframes)), start_(start), end_(end) {
  if (keyframes_.empty()) throw std::logic_error("SpeedProfile: no keyframes");
}

double SpeedProfile::held(double t) const {
  if (t <= keyframes_.front().first) return keyframes_.front().second;
  if (t >= keyframes_.back().first) return keyframes_.back().second;
  const auto next = std::upper_bound(
      keyframes_.begin(), keyframes_.end(), t,
      [](double time, const std::pair<double, double>& k) { return time < k.first; });
  const auto& [t1, v1] = *next;
  const auto& [t0, v0] = *(next - 1);
  return v0 + (v1 - v0) * (t - t0) / (t1 - t0);
}

double SpeedProfile::at(double t) const {
  return t < start_ || t > end_ ? 0.0 : held(t);
}

double SpeedProfile::distance(double a, double b) const {
  a = std::max(a, start_);
  b = std::min(b, end_);
  if (!(b > a)) return 0;
  // Linear between breakpoints: the keyframe times inside (a, b) split it into trapezoids.
  double total = 0, from = a;
  for (const auto& [t, v] : keyframes_) {
    if (t <= from) continue;
    if (t >= b) break;
    total += 0.5 * (held(from) + v) * (t - from);
    from = t;
  }
  return total + 0.5 * (held(from) + held(b)) * (b - from);
}

}  // namespace upf
