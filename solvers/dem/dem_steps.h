// The DEM solver's sub-steps (dem_solver.h), written once for every executor: DemSolver runs
// them on the CPU executor; a device pipeline can run them on its backends with the same bits.
// Velocity Verlet (as in LIGGGHTS): kick half, drift, forces at the new positions with the
// half-step velocities, kick half; each sub-step's forces are followed by the pair forces' gather
// and, with bodies, the reactions on their boundary particles. C++17: nvcc builds it too.
#pragma once

#include "framework/executors/particle_range.h"
#include "solvers/dem/dem_stages.h"

namespace upf {

// The views a DEM step works on.
struct DemArrays {
  DemModel model;
  DemContactView contacts;
  DemPairTable pairs;
  ParticleRange owned;    // the solver's grains
  ParticleRange holders;  // the grains that hold candidates: owned, then ghosts on split worlds
  ParticleRange rigid;    // rigid boundary particles whose reactions are wanted (may be empty)
  Vec3* x;
  Vec3* v;
  Vec3* w;  // angular velocity
  const Real* mass;
  const Real* radius;
  const ParticleType* type;
  const MaterialId* material;
  const ContainerBox* boxes;
  Vec3 gravity;
  const GrainFluidState* fluid;  // null without liquid
  Vec3* fluid_force;             // the step's average fluid force on each grain
  Vec3* force;                   // on each grain, the last sub-step's
  Vec3* torque;
  Vec3* boundary_force;  // the reactions on rigid particles; null: none wanted
  // Recorded for export (DemContactRecord); null: not recorded.
  Vec3* wall_normal;
  Vec3* wall_shear;
  Real* contact_load;
};

// Contact, gravity and fluid forces at the current state (the fluid force and the walls' forces
// added to the step's averages with weight `weight`), then each grain's share of the pairs its
// partners hold. `first`: the step's first sub-step, where the walls' averages start again;
// `last`: its last, whose contact loads are recorded.
template <class Executor>
void run_dem_forces(const Executor& exec, const DemArrays& a, Real h, Real t_in_step, Real weight,
                    bool first, bool last) {
  DemContactRecord record;
  record.wall_normal = a.wall_normal;
  record.wall_shear = a.wall_normal ? a.wall_shear : nullptr;
  record.weight = weight;
  record.restart = first;
  // The forces and the candidates' records are read back only by the grains (and body particles)
  // themselves: no ghost refresh until the kick, which refreshes every array (the step averages
  // the liquid reads included).
  exec.run_unshared(
      a.holders,
      DemForcesStage{a.model,  a.contacts, a.pairs,       a.x,     a.v,       a.w,   a.mass,
                     a.radius, a.type,     a.material,    a.boxes, a.gravity, h,     t_in_step,
                     a.fluid,  weight,     a.fluid_force, a.force, a.torque,  record});
  exec.run_unshared(a.owned, DemGatherPairsStage{a.contacts, a.force, a.torque});
  if (last && a.contact_load)
    exec.run_unshared(a.owned, DemContactLoadStage{a.contacts, a.contact_load});
}

// The forces at the state a run starts from, which velocity Verlet's first half kick needs.
template <class Executor>
void run_dem_first_forces(const Executor& exec, const DemArrays& a, Real h) {
  run_dem_forces(exec, a, h, 0, 0, true, true);
}

// v += F h_kick / m, w += tau h_kick / I, then x += v h_drift.
template <class Executor>
void run_dem_kick_drift(const Executor& exec, const DemArrays& a, Real h_kick, Real h_drift) {
  exec.run(a.owned,
           DemKickDriftStage{a.force, a.torque, a.mass, a.radius, h_kick, h_drift, a.x, a.v, a.w});
}

// `substeps` sub-steps of h filling a world step of dt; `run(name, work)` times each stage
// ("dem_integration", "dem_contacts") as the world's stage runner does.
template <class Executor, class Run>
void run_dem_substeps(const Executor& exec, const DemArrays& a, Real dt, int substeps, Real h,
                      Run&& run) {
  for (int k = 0; k < substeps; ++k) {
    run("dem_integration", [&] { run_dem_kick_drift(exec, a, Real(0.5) * h, h); });
    run("dem_contacts", [&] {
      run_dem_forces(exec, a, h, Real(k + 1) * h, h / dt, k == 0, k + 1 == substeps);
      if (a.boundary_force)
        exec.run_unshared(a.rigid, DemBoundaryReactionStage{a.contacts, h / dt, a.boundary_force});
    });
    run("dem_integration", [&] { run_dem_kick_drift(exec, a, Real(0.5) * h, 0); });
  }
}

}  // namespace upf
