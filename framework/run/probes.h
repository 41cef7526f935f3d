// Probes: numbers measured on the liquid while a scene runs (written to probes.csv).
//   extent    the largest (or smallest) coordinate of liquid along an axis, optionally only inside
//             a region: the surge front of a dam break is the largest x near the floor. The
//             particle centre's, or with `surface` the particle's surface, half a spacing out.
//   height    the liquid surface height along the up axis in a thin column at a point: the top
//             particle centre plus half a spacing, or (method volume) the liquid volume per unit
//             area under a 2D Wendland kernel, which a splash above the surface barely moves,
//             as it barely moves a wave gauge.
//   pressure  the mean pressure of liquid particles inside a small sphere, or (method kernel)
//             its Shepard-normalised Wendland interpolation at the centre: on a wall, the
//             pressure a flush-mounted sensor reads.
// A probe that sees no liquid reports NaN (written as "nan").
#pragma once

#include "framework/particles/particles.h"
#include "framework/scene/scene.h"

namespace upf {

double evaluate_probe(const ProbeDesc& probe, const Particles& particles, Real spacing);

// The SI unit of what a probe of `kind` measures: "m" for extents and heights, "Pa" for
// pressures.
const char* probe_unit(ProbeKind kind);

}  // namespace upf
