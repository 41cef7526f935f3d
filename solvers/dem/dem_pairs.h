// Per-pair contact constants, computed once from the granular materials of the scene: grain with
// grain (every pair of materials), grain with a container wall (a rigid plane), and grain with a
// body's boundary particle (a rigid sphere of half a spacing). Between two granular materials,
// restitution, friction, rolling friction and cohesion are the means of the two; against walls
// and bodies the grain's own values hold (they are ideally rigid), its wall_friction for friction.
// Effective moduli (Hertz): 1/E* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j and
// 1/G* = 2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j (Mindlin 1949; DEM-solutions EDEM guide).
// Linear: a material's normal_stiffness is k_n between two of its grains (and against a wall);
// two materials take the harmonic mean 2 / (1/k_a + 1/k_b). Tangential: k_t = k_n 2(1-nu)/(2-nu),
// Mindlin's ratio of the two stiffnesses.
#pragma once

#include <vector>

#include "framework/materials/material.h"
#include "solvers/dem/dem_contact.h"
#include "solvers/dem/dem_views.h"

namespace upf {

struct DemGrainMaterial {
  bool granular = false;
  Real radius = 0, mass = 0, density = 0;
  Real youngs = 0, poisson = 0, k_n = 0;
  Real restitution = 1, friction = 0, rolling_friction = 0, cohesion = 0;
  Real wall_friction = 0;  // against container walls and bodies
};

class DemPairs {
 public:
  // `spacing` sets the radius of grains with radius 0 and of boundary particles.
  DemPairs(const MaterialTable& materials, Real spacing);

  const DemGrainMaterial& grain(MaterialId m) const { return grains_[m]; }
  const DemPairParams& pair(MaterialId a, MaterialId b) const { return pairs_[a * n_ + b]; }
  const DemPairParams& wall(MaterialId a) const { return walls_[a]; }
  const DemPairParams& boundary(MaterialId a) const { return boundary_[a]; }
  Real boundary_radius() const { return boundary_radius_; }
  DemPairTable table() const {
    return {pairs_.data(), walls_.data(), boundary_.data(), n_, boundary_radius_};
  }

  // The shortest contact time over all pairs: the linear model's pi / (omega0 sqrt(1 - zeta^2)),
  // or for Hertz the Rayleigh time pi R sqrt(rho / G) / (0.1631 nu + 0.8766) of the
  // smallest grain (Li et al. 2005), which bounds the Hertz contact times from below.
  Real shortest_contact_time(DemModel model) const;

 private:
  DemPairParams make(const DemGrainMaterial& a, const DemGrainMaterial* b, Real r_other,
                     bool rigid_other) const;

  std::size_t n_ = 0;
  Real boundary_radius_ = 0;
  std::vector<DemGrainMaterial> grains_;
  std::vector<DemPairParams> pairs_, walls_, boundary_;
};

}  // namespace upf
