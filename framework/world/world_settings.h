// Settings that hold for the whole world: gravity, resolution, time stepping, stability limits.
#pragma once

#include "framework/core/vec3.h"
#include "framework/world/periodic_box.h"

namespace upf {

struct TimeSettings {
  double end = 1.0;       // s
  double dt_min = 1e-6;   // s
  double dt_max = 5e-3;   // s
  double cfl = 0.4;       // 1: dt <= cfl * spacing / |v|max
  double fixed_dt = 0.0;  // s; > 0 replaces the adaptive step
};

struct WorldSettings {
  Vec3 gravity{0, Real(-9.81), 0};  // m/s^2
  Real spacing = Real(0.02);        // m, the initial particle spacing
  Real support_factor = 2;          // support radius / spacing
  TimeSettings time;
  double max_speed = 100;  // m/s: faster particles stop the run as unstable
  int reorder_every = 10;  // steps between locality reorders; 0 disables
  PeriodicBox periodic;    // the axes along which the world repeats (none by default)

  Real support_radius() const { return support_factor * spacing; }
};

}  // namespace upf
