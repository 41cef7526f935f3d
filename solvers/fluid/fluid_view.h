// What every fluid solver shares: a raw view of the particle arrays, the neighbour lists
// (fluid -> fluid, fluid -> boundary) and the per-material constants. Per-particle functions take
// this view by value so the same source runs in OpenMP loops and, later, in CUDA kernels.
#pragma once

#include <vector>

#include "framework/core/particle_type.h"
#include "framework/kernels/cubic_spline.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"

namespace upf {

class World;

struct FluidView {
  const Vec3* x = nullptr;
  const Vec3* v = nullptr;
  const Real* mass = nullptr;
  const ParticleType* type = nullptr;
  const MaterialId* material = nullptr;
  const Real* boundary_volume = nullptr;
  const Real* rest_density = nullptr;        // per material
  const Real* viscosity = nullptr;           // per material, kinematic [m^2/s]
  const Real* boundary_viscosity = nullptr;  // per material, kinematic [m^2/s]
  NeighbourView fluid;                       // fluid -> fluid
  NeighbourView boundary;                    // fluid -> frozen and rigid
  CubicSplineKernel kernel;
};

// Per-material constants, copied once in prepare() into arrays a view can point at.
struct FluidMaterialTable {
  std::vector<Real> rest_density, viscosity, boundary_viscosity;
  void load(const World& world);
};

// Neighbour-list handles for the lists every fluid solver needs.
struct FluidNeighbourHandles {
  int fluid = -1, boundary = -1;
  void request(World& world);
};

FluidView make_fluid_view(const World& world, const FluidMaterialTable& materials,
                          const FluidNeighbourHandles& lists);

}  // namespace upf
