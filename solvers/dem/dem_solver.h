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
// Determinism: each grain gathers its own contacts (pairs are computed from both sides with
// forces that are exact opposites) and keeps its own contact history; a boundary particle reads
// the forces back from its grains' histories. No atomics, no scatter.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/params/param_spec.h"
#include "framework/solver/solver.h"
#include "solvers/dem/dem_contact.h"
#include "solvers/dem/dem_contact_history.h"
#include "solvers/dem/dem_pairs.h"

namespace upf {

inline constexpr const char* kAngularVelocityField = "angular_velocity";
inline constexpr const char* kRadiusField = "radius";
inline constexpr const char* kForceField = "dem.force";    // N, on each grain, last sub-step
inline constexpr const char* kTorqueField = "dem.torque";  // N m

class DemSolver : public Solver {
 public:
  static std::vector<ParamSpec> param_specs();
  DemSolver(DemModel model, const ParamValues& params, std::vector<MaterialId> materials);

  std::string_view name() const override {
    return model_ == DemModel::Linear ? "dem_linear" : "dem_hertz";
  }
  void prepare(World& world) override;
  Real max_time_step(const World& world) const override;
  void step(World& world, Real dt) override;
  SolverStats stats() const override { return stats_; }

  // The longest sub-step the materials allow, s.
  Real substep() const { return substep_; }
  // Contacts dropped because a grain had more than DemContactHistory::kSlots (0 expected).
  std::size_t dropped_contacts() const { return dropped_; }

 private:
  void substep_forces(World& world, Real t_in_step);
  void substep_reactions(World& world, Real weight);
  void kick(World& world, Real h);   // v += F h / m, w += tau h / I
  void drift(World& world, Real h);  // x += v h

  DemModel model_;
  double substep_fraction_;
  std::vector<MaterialId> materials_;
  std::vector<char> mine_;  // by material
  std::unique_ptr<DemPairs> pairs_;
  DemContactHistory history_;
  int grains_list_ = -1, reaction_list_ = -1;
  Real substep_ = 0, h_ = 0;
  bool primed_ = false;  // forces computed for the current positions
  std::vector<std::uint8_t> overflow_;
  std::size_t dropped_ = 0;
  SolverStats stats_;
};

}  // namespace upf
