// An emitter's speed over time: zero before `start` and after `end`, in between a constant or
// keyframes (time, speed) joined linearly and held flat beyond the first and last, like
// prescribed motion. Its integral is exact (trapezoids between keyframes), so an emitter's
// count of layers is a function of time alone, the same for any step sizes up to rounding.
#pragma once

#include <utility>
#include <vector>

namespace upf {

class SpeedProfile {
 public:
  SpeedProfile() = default;
  // `keyframes` sorted by time, at least one; a single one is a constant speed.
  SpeedProfile(std::vector<std::pair<double, double>> keyframes, double start, double end);

  double at(double t) const;
  // The distance travelled from `a` to `b` (a <= b): the integral of at() over [a, b].
  double distance(double a, double b) const;
  double start() const { return start_; }
  double end() const { return end_; }

 private:
  double held(double t) const;  // the keyframes' speed, ignoring start and end

  std::vector<std::pair<double, double>> keyframes_;
  double start_ = 0, end_ = 0;
};

}  // namespace upf
