// Discrete element method for granular materials: soft spheres with a contact model
// (dem_contact.h) integrated by velocity Verlet in sub-steps, so that each contact lasts
// 1 / substep_fraction sub-steps or more, inside the world's step.
//
// Contacts: grain-grain, grain-container wall (the six inner faces of each container as exact
// planes), and grain-body boundary particle (rigid spheres of half a spacing: the two sample
// layers of a body lie 0.5 and 1.5 spacings under its mesh, so the spheres' outer surface is
// the mesh's). Forces on rigid boundary particles go to the shared boundary_force field,
// averaged over the sub-steps, and from there through the same per-body sum as the fluid
// coupling into Bullet. Bodies move at their step-start velocity during the sub-steps.
//
// Grains in a liquid feel drag (Di Felice 1994) and buoyancy (dem_fluid_drag.h) from the liquid
// interpolated around them at the step's start; the liquid neighbours gather the opposite force,
// averaged over the sub-steps, through the coupling array CouplingArray::LiquidForce, so momentum
// is conserved.
//
// Determinism: each pair of grains is computed once, by the grain with the lower id, which holds
// the pair and its spring (dem_contact_list.h); in a second pass the other grain gathers the
// exact opposite force (and the matching torque) from it, as a boundary particle reads its forces
// back from its grains' contacts. No atomics, no scatter.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/params/param_binding.h"
#include "framework/solver/solver.h"
#include "solvers/dem/dem_contact.h"
#include "solvers/dem/dem_contact_list.h"
#include "solvers/dem/dem_fluid_drag.h"
#include "solvers/dem/dem_pairs.h"
#include "solvers/dem/dem_spring_state.h"
#include "solvers/dem/dem_step_setup.h"
#include "solvers/dem/dem_steps.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

inline constexpr const char* kAngularVelocityField = "angular_velocity";
inline constexpr const char* kRadiusField = "radius";
inline constexpr const char* kForceField = "dem.force";    // N, on each grain, last sub-step
inline constexpr const char* kTorqueField = "dem.torque";  // N m
// Recorded for export (DemContactRecord): the container walls' normal and tangential forces on
// each grain averaged over the step (N), and the sum of |F| over its contacts (N, exported).
inline constexpr const char* kWallNormalField = "dem.wall_normal";
inline constexpr const char* kWallShearField = "dem.wall_shear";
inline constexpr const char* kContactLoadField = "dem.contact_load";
inline constexpr const char* kFluidWeightSumField = "dem.fluid_weight_sum";
inline constexpr const char* kFluidForceField = "dem.fluid_force";

struct DemParams {
  double substep_fraction = 0;  // of the shortest contact time
};

class DemSolver : public Solver {
 public:
  static ParamBinding<DemParams> param_binding();
  DemSolver(DemModel model, const DemParams& params, std::vector<MaterialId> materials);

  std::string_view name() const override {
    return model_ == DemModel::Linear ? "dem_linear" : "dem_hertz";
  }
  void prepare(World& world) override;
  Real max_time_step(const World& world) const override;
  std::vector<std::string> stages() const override;
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override { return stats_; }
  // "<name>_walls": the grains' force on each container face (dem_wall_forces.h), when the scene
  // has containers.
  std::vector<SolverTable> tables(const World& world) const override;
  std::vector<std::vector<double>> table_rows(const World& world,
                                              const Particles& state) const override;
  // Split over ranks, the springs follow their grains (dem_contact_list.h).
  void split_over(const ParticleDomain& domain) override { domain_ = &domain; }
  void save_state(StateWriter& out) const override;
  void restore_state(StateReader& in) override;

  // The longest sub-step the materials allow, s.
  Real substep() const { return substep_; }
  // The step's constants as plain values, for a device pipeline (after prepare).
  DemStepSetup step_setup(const World& world) const;
  // The springs carried between steps, for a device pipeline that takes the step over.
  DemSpringState spring_state() const;
  void set_spring_state(const DemSpringState& state);

 private:
  void interpolate_fluid(World& world);
  void liquid_reactions(World& world);
  // The step's views for the shared sub-steps (dem_steps.h).
  DemArrays arrays(World& world);

  DemModel model_;
  double substep_fraction_;
  std::vector<MaterialId> materials_;
  OwnedParticles owned_;                    // my grains, this step
  std::vector<std::uint32_t> holders_;      // my grains, then my ghost grains (split worlds)
  const ParticleDomain* domain_ = nullptr;  // the world's ranks; null: one rank
  std::vector<std::uint32_t> rigid_;        // rigid boundary particles, this step
  std::unique_ptr<DemPairs> pairs_;
  DemContactList contacts_;  // this world step's candidates and their springs
  FieldHandle<Real> radius_;
  FieldHandle<Vec3> angular_velocity_, force_, torque_, wall_normal_, wall_shear_;
  FieldHandle<Real> contact_load_;
  int grains_list_ = -1, reaction_list_ = -1;
  Real substep_ = 0, h_ = 0;
  Real skin_ = 0;        // m, how far contact lists reach beyond the longest contact
  bool primed_ = false;  // forces computed for the current positions
  // Grain-liquid coupling (when the scene has liquid).
  int grain_liquid_list_ = -1, liquid_grain_list_ = -1, grain_voidage_list_ = -1;
  std::vector<Real> liquid_density_, liquid_viscosity_;  // by material
  std::vector<GrainFluidState> fluid_;                   // by particle, this step
  std::vector<Vec3> start_position_;                     // grains at the step's start
  // Read by the grains' liquid neighbours, so fields (scratch: ghosts carry them).
  FieldHandle<Real> fluid_weight_sum_;  // sum_j V_j W_ij
  FieldHandle<Vec3> fluid_force_;       // the step's average fluid force on each grain
  SolverStats stats_;
};

}  // namespace upf
