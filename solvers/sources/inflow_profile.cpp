#include "solvers/sources/inflow_profile.h"

#include <algorithm>
#include <cmath>

namespace upf {

bool parse_inflow_profile(std::string_view name, InflowProfileKind& kind) {
  if (name == "uniform") {
    kind = InflowProfileKind::Uniform;
  } else if (name == "parabolic") {
    kind = InflowProfileKind::Parabolic;
  } else if (name == "open_channel") {
    kind = InflowProfileKind::OpenChannel;
  } else {
    return false;
  }
  return true;
}

InflowProfile::InflowProfile(InflowProfileKind kind, const std::vector<Eigen::Vector3d>& opening,
                             const Eigen::Vector3d& width, const Eigen::Vector3d& height,
                             bool circle, double spacing, const Eigen::Vector3d& up)
    : kind_(kind), width_(width), height_(height), up_(up), circle_(circle) {
  if (uniform() || opening.empty()) return;
  // The duct's wall or the bed lies where the lattice's cells end: half a spacing beyond the
  // outermost points of a rectangle or a bed, as a fluid block's particles sit half a spacing
  // inside its box, and for a disc at the radius of the lattice's area (points x h^2), so the
  // centre's speed is twice the mean, as in Hagen-Poiseuille flow.
  double lo = opening.front().dot(up_), hi = lo;
  for (const Eigen::Vector3d& o : opening) {
    half_width_ = std::max(half_width_, std::abs(o.dot(width_)));
    half_height_ = std::max(half_height_, std::abs(o.dot(height_)));
    lo = std::min(lo, o.dot(up_));
    hi = std::max(hi, o.dot(up_));
  }
  constexpr double kPi = 3.14159265358979323846;
  radius_ = spacing * std::sqrt(double(opening.size()) / kPi);
  half_width_ += 0.5 * spacing;
  half_height_ += 0.5 * spacing;
  bed_ = lo - 0.5 * spacing;
  depth_ = hi - lo + spacing;
  double sum = 0;
  for (const Eigen::Vector3d& o : opening) sum += shape(o);
  scale_ = double(opening.size()) / sum;
}

double InflowProfile::shape(const Eigen::Vector3d& offset) const {
  switch (kind_) {
    case InflowProfileKind::Uniform:
      return 1;
    case InflowProfileKind::Parabolic: {
      const double u = offset.dot(width_), v = offset.dot(height_);
      if (circle_) return std::max(0.0, 1 - (u * u + v * v) / (radius_ * radius_));
      const double a = 1 - (u * u) / (half_width_ * half_width_);
      const double b = 1 - (v * v) / (half_height_ * half_height_);
      return std::max(0.0, a) * std::max(0.0, b);
    }
    case InflowProfileKind::OpenChannel: {
      const double s = std::clamp((offset.dot(up_) - bed_) / depth_, 0.0, 1.0);
      return 2 * s - s * s;
    }
  }
  return 1;
}

double InflowProfile::factor(const Eigen::Vector3d& offset) const {
  return uniform() ? 1.0 : scale_ * shape(offset);
}

}  // namespace upf
