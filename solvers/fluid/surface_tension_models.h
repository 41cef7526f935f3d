// The surface tension models of the shared fluid pieces (surface_forces.h), registered by name for
// the scenes' "surface_tension_model", and how a liquid's sigma [N/m] becomes Akinci's gamma.
#pragma once

#include <string>

#include "framework/solver/registry.h"
#include "solvers/fluid/surface_force_view.h"

namespace upf {

void register_surface_tension_models(Registry& registry);

// The model of a registered name, the default (the first registered) for an empty one, None for
// an unknown one.
SurfaceTensionModel surface_tension_model_named(const std::string& name);

// Akinci's gamma that gives a liquid of rest density rho0 the surface tension sigma [N/m] at
// particle spacing s and support radius H: the work per area to split the initial lattice
// (s^3 per particle) along a plane, summed pair by pair, is 2 sigma (0.76 of the continuum value
// of Kirkwood & Buff, akinci_kernels.h, at H = 2 s). Also the scale of the adhesion,
// beta = ratio * gamma.
double akinci_gamma_for_sigma(double sigma, double rest_density, double spacing,
                              double support_radius);

// The continuum surface force's c0 (continuum_surface_force.h): the colour gradient
// |sum_j V_j grad W_ij| of the initial lattice (V = s^3) summed over the particles under a flat
// face, per unit area of the face. 0.51 at H = 2 s: the particles see only the inner half of the
// colour's jump.
double csf_face_gradient_per_area(double spacing, double support_radius);

}  // namespace upf
