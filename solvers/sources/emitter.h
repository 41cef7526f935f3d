// An emitter: a nozzle that pours liquid into the scene, layer by layer, like SPlisHSPlasH's box
// and circle emitters and FleX's emitter discs. The nozzle's opening (a disc or a rectangle, at
// `center`, facing `direction`) carries a square lattice at the liquid's spacing h; `area` is
// its points times h^2. With D(t) the distance the inflow has travelled since the start (the
// integral of the speed profile), layer k enters once D >= k h, at D - k h in front of the
// opening, with the nozzle's velocity. So after time t the emitter has placed
// floor(D / h) + 1 layers: the mass rate is rho0 * area * v exactly, to within one layer, at any
// step size. A speed that falls to zero stops the flow and a later rise restarts it.
//
// Particles come in before a step (particle_source.h) with new ids, appended in lattice order.
// While the emitter flows, the liquid in its inflow buffer (the opening's cross-section, from
// the opening to `buffer` ahead of it) is given the nozzle's velocity before every step, as the
// inlet buffer of Tafuni et al. 2018 (DualSPHysics) imposes it: the layers then keep their
// spacing h against the back-pressure of a pool or a channel they pour into, where a free
// layer would be slowed and the next one placed onto it.
//
// A velocity profile (inflow_profile.h) scales the speed at each lattice point by a factor f
// that averages 1 over the opening: each point is then a column of its own, whose layer k enters
// once f D >= k h, so the columns stay a spacing apart along the flow and the rate is still
// rho0 * area * v. A uniform profile (f = 1) is the one-layer-at-a-time emitter above, bit for
// bit.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "framework/particles/particles.h"
#include "framework/world/particle_source.h"
#include "solvers/sources/inflow_profile.h"
#include "solvers/sources/speed_profile.h"

namespace upf {

struct EmitterDesc {
  std::string name;  // "emitter 0" or the scene's name, for errors and checkpoints
  MaterialId material = 0;
  Real particle_mass = 0;  // rho0 h^3, as the fluid blocks' particles
  double spacing = 0;      // h
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // unit
  // The opening's lattice points, relative to `center`, in the plane normal to `direction`.
  std::vector<Eigen::Vector3d> opening;
  // The opening's shape in its plane (axes `width`, `height`): a disc of `radius` when
  // `circle`, else |u| <= half_width, |v| <= half_height (lattice points' reach).
  Eigen::Vector3d width = Eigen::Vector3d::UnitX(), height = Eigen::Vector3d::UnitZ();
  bool circle = true;
  double radius = 0, half_width = 0, half_height = 0;
  double buffer = 0;  // how far ahead of the opening the inflow buffer reaches (m)
  SpeedProfile speed;
  InflowProfile profile;  // across the opening; uniform by default
  // At most this many layers (a volume to emit, a budget that closes it); the largest integer:
  // no limit.
  std::uint64_t max_layers = std::numeric_limits<std::uint64_t>::max();
  // A budget that must not be passed: a layer beyond `budget_layers` ends the run with an
  // InputError at `budget_where` (the scene's max_particles) instead.
  std::uint64_t budget_layers = std::numeric_limits<std::uint64_t>::max();
  std::string budget_where;
  // at_limit "reuse": at most this many of its particles in the scene at once, counting those
  // the sinks that reuse into it gave back (Emitter::give_back); the largest integer: none.
  std::uint64_t live_limit = std::numeric_limits<std::uint64_t>::max();
};

// How many particles the emitter has placed once the inflow has travelled `travelled` (its
// max_layers applied, the budget not): the scene's memory check and budget use it.
double particles_due(const EmitterDesc& desc, double travelled);

class Emitter : public ParticleSource {
 public:
  explicit Emitter(EmitterDesc desc);
  std::string_view name() const override { return desc_.name; }
  bool may_change(double time, double dt) const override;
  SourceChange apply(Particles& particles, const SourceStep& step) override;
  void save_state(StateWriter& out) const override;
  void restore_state(StateReader& in) override;

  // The opening's area, points x h^2: the flow rate is rho0 * area() * speed.
  double area() const { return double(desc_.opening.size()) * desc_.spacing * desc_.spacing; }
  // A sink that reuses into this emitter took `particles`: room for as many again.
  void give_back(std::uint64_t particles) { returned_ += particles; }
  // Particles placed so far, and given back by sinks.
  std::uint64_t created() const { return created_; }
  std::uint64_t returned() const { return returned_; }
  // Layers placed so far (of the fastest column, with a profile).
  std::uint64_t layers() const { return layers_; }

 private:
  // Layers of column `i` due once the inflow has travelled `travelled`.
  std::uint64_t layers_due(std::size_t i, double travelled) const;
  // Whether some column has a layer due at `travelled`.
  bool any_due(double travelled) const;
  // Whether `x` is in the inflow buffer.
  bool in_buffer(const Eigen::Vector3d& x) const;

  EmitterDesc desc_;
  double clock_ = 0;            // the time `travelled_` reaches
  double travelled_ = 0;        // D(clock_)
  std::uint64_t layers_ = 0;    // the most layers of any column (every column's, when uniform)
  std::vector<double> factor_;  // each column's profile factor
  std::vector<std::uint64_t> column_layers_;  // each column's layers so far
  std::vector<std::uint64_t> due_;            // apply()'s layers due per column
  std::uint64_t created_ = 0, returned_ = 0;  // for live_limit
};

}  // namespace upf
