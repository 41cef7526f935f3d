// The velocity profile across an emitter's opening: how the inflow's speed varies over the
// opening, as an inlet's imposed velocity profile (Tafuni et al. 2018, "A versatile algorithm for
// the treatment of open boundary conditions in SPH", Comput. Methods Appl. Mech. Eng.; the
// inflow of DualSPHysics). The factor at a lattice point scales the emitter's speed there; the
// factors average 1 over the opening's lattice, so `speed` stays the mean speed and the flow
// rate stays rho0 * A * speed whatever the profile.
//   uniform       1 everywhere (a plug flow, the default).
//   parabolic     laminar flow in a duct that ends at the opening: 1 - (r / R)^2 in a circle
//                 (Hagen-Poiseuille; R the radius of the lattice's area, so the centre moves at
//                 twice the mean), (1 - (u / a)^2)(1 - (v / b)^2) in a rectangle (zero half a
//                 spacing beyond the outermost lattice points, where the duct's wall would be).
//   open_channel  laminar flow of a film or a wide open channel (a half-parabola, Bird,
//                 Stewart & Lightfoot, 2.2): 2 s - s^2 with s the height above the opening's
//                 lowest edge (against gravity) over its depth: zero on the bed, fastest at the
//                 free surface.
#pragma once

#include <Eigen/Core>
#include <string_view>
#include <vector>

namespace upf {

enum class InflowProfileKind { Uniform, Parabolic, OpenChannel };

// Parses a profile's name; false for an unknown one.
bool parse_inflow_profile(std::string_view name, InflowProfileKind& kind);

class InflowProfile {
 public:
  InflowProfile() = default;
  // `opening`: the lattice points (relative to the centre) the factors are normalised over;
  // `width`, `height`: the opening's unit axes; `circle`: a disc (else a rectangle);
  // `up`: a unit vector in the opening's plane pointing away from the bed (open_channel only).
  InflowProfile(InflowProfileKind kind, const std::vector<Eigen::Vector3d>& opening,
                const Eigen::Vector3d& width, const Eigen::Vector3d& height, bool circle,
                double spacing, const Eigen::Vector3d& up);

  bool uniform() const { return kind_ == InflowProfileKind::Uniform; }
  // The factor at `offset` from the opening's centre (its part along the direction ignored):
  // 1 for a uniform profile; never negative.
  double factor(const Eigen::Vector3d& offset) const;

 private:
  double shape(const Eigen::Vector3d& offset) const;  // before normalising

  InflowProfileKind kind_ = InflowProfileKind::Uniform;
  Eigen::Vector3d width_ = Eigen::Vector3d::UnitX(), height_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitY();
  bool circle_ = true;
  double radius_ = 0, half_width_ = 0, half_height_ = 0;  // where the shape reaches zero
  double bed_ = 0, depth_ = 1;                            // open_channel: along up_
  double scale_ = 1;                                      // 1 / the lattice's mean shape
};

}  // namespace upf
