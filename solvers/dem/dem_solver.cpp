#include "solvers/dem/dem_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/world/world.h"
#include "solvers/dem/dem_stages.h"
#include "solvers/dem/dem_steps.h"
#include "solvers/dem/dem_wall_forces.h"

namespace upf {

namespace {

constexpr TypeMask kGranularMask = mask_of(ParticleType::Granular);

// Contact lists reach this many spacings beyond the longest contact distance, and a world step
// lets no grain move more than half of it, so no contact starts unlisted. Short lists are most
// of the DEM's speed: at 0.2, a grain of half a spacing has about 7 candidates, not 33.
constexpr Real kSkinPerSpacing = Real(0.2);

}  // namespace

ParamBinding<DemParams> DemSolver::param_binding() {
  ParamBinding<DemParams> b;
  b.add({"substep_fraction", "1", 0.05, 1e-4, 0.5,
         "DEM sub-step as a fraction of the shortest contact time (linear: the contact time; "
         "Hertz: the Rayleigh time)"},
        &DemParams::substep_fraction);
  return b;
}

DemSolver::DemSolver(DemModel model, const DemParams& params, std::vector<MaterialId> materials)
    : model_(model), substep_fraction_(params.substep_fraction), materials_(std::move(materials)) {}

void DemSolver::prepare(World& world) {
  Particles& p = world.particles();
  owned_.set_materials(world.materials().size(), materials_);
  pairs_ = std::make_unique<DemPairs>(world.materials(), world.settings().spacing);
  substep_ = Real(substep_fraction_) * pairs_->shortest_contact_time(model_);

  radius_ = p.declare_scalar(kRadiusField, 0, true);
  angular_velocity_ = p.declare_vector(kAngularVelocityField, {}, true);
  force_ = p.declare_vector(kForceField);
  torque_ = p.declare_vector(kTorqueField);
  wall_normal_ = p.declare_vector(kWallNormalField);
  wall_shear_ = p.declare_vector(kWallShearField);
  contact_load_ = p.declare_scalar(kContactLoadField, 0, true);
  std::vector<Real>& radius = p[radius_];
  primed_ = false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Granular) radius[i] = pairs_->grain(p.material[i]).radius;
  contacts_.clear();
  Real reach = 0;
  for (MaterialId m : materials_) {
    const Real r = pairs_->grain(m).radius;
    reach = std::max({reach, 2 * r, r + pairs_->boundary_radius()});
  }
  skin_ = kSkinPerSpacing * world.settings().spacing;
  const Real list_radius = reach + skin_;
  grains_list_ =
      world.request_neighbours(kGranularMask, kGranularMask | kBoundaryMask, list_radius);
  if (world.coupling().active(CouplingArray::BoundaryForce) && p.count(ParticleType::Rigid) > 0)
    reaction_list_ =
        world.request_neighbours(mask_of(ParticleType::Rigid), kGranularMask, list_radius);
  if (p.count(ParticleType::Liquid) > 0) {
    fluid_weight_sum_ = p.declare_scratch_scalar(kFluidWeightSumField);
    fluid_force_ = p.declare_scratch_vector(kFluidForceField);
    grain_liquid_list_ = world.request_neighbours(kGranularMask, kLiquidMask);
    // The voidage is an SPH sum over the whole kernel support, farther than contacts reach.
    grain_voidage_list_ = world.request_neighbours(kGranularMask, kGranularMask);
    liquid_grain_list_ = world.request_neighbours(kLiquidMask, kGranularMask);
    const MaterialTable& mats = world.materials();
    liquid_density_.assign(mats.size(), 0);
    liquid_viscosity_.assign(mats.size(), 0);
    for (std::size_t m = 0; m < mats.size(); ++m)
      if (mats[MaterialId(m)].type == ParticleType::Liquid) {
        liquid_density_[m] = Real(mats[MaterialId(m)].param("density"));
        liquid_viscosity_[m] = Real(mats[MaterialId(m)].param("drag_viscosity"));
      }
  }
}

Real DemSolver::max_time_step(const World& world) const {
  // Over a world step a pair may close in by at most the lists' skin: each grain moves at most
  // half of it. Through the world: with a device pipeline it is a reduction there.
  const OwnedMaterials owns = owned_.materials();
  const Real fastest =
      std::sqrt(world.max_speed_squared(ParticleType::Granular, owns.flags, owns.count));
  if (fastest <= 0) return std::numeric_limits<Real>::max();
  return Real(0.5) * skin_ / fastest;
}

DemStepSetup DemSolver::step_setup(const World& world) const {
  DemStepSetup s;
  s.model = model_;
  const DemPairTable table = pairs_->table();
  s.materials = table.n;
  s.pairs.assign(table.pairs, table.pairs + table.n * table.n);
  s.walls.assign(table.walls, table.walls + table.n);
  s.boundary.assign(table.boundary, table.boundary + table.n);
  s.boundary_radius = table.boundary_radius;
  const OwnedMaterials owns = owned_.materials();
  s.owns.assign(owns.flags, owns.flags + owns.count);
  s.boxes = world.containers();
  s.gravity = world.settings().gravity;
  s.substep = substep_;
  s.skin = skin_;
  s.list_radius = world.neighbour_radius(grains_list_);
  s.reactions = reaction_list_ >= 0;
  s.liquid = grain_liquid_list_ >= 0;
  s.liquid_force = s.liquid && world.coupling().active(CouplingArray::LiquidForce);
  s.liquid_density = liquid_density_;
  s.liquid_viscosity = liquid_viscosity_;
  s.radius = kRadiusField;
  s.angular_velocity = kAngularVelocityField;
  s.force = kForceField;
  s.torque = kTorqueField;
  s.wall_normal = kWallNormalField;
  s.wall_shear = kWallShearField;
  s.contact_load = kContactLoadField;
  return s;
}

DemSpringState DemSolver::spring_state() const {
  DemSpringState state;
  state.primed = primed_;
  contacts_.springs_into(state);
  return state;
}

void DemSolver::set_spring_state(const DemSpringState& state) {
  primed_ = state.primed;
  contacts_.set_springs(state);
}

std::vector<std::string> DemSolver::stages() const {
  return {"dem_contacts", "dem_integration"};
}

void DemSolver::step(World& world, Real dt, StageRunner& run) {
  stats_ = SolverStats{};
  const int n = std::max(1, int(std::ceil(double(dt) / double(substep_) - 1e-9)));
  h_ = dt / Real(n);
  const bool liquid = grain_liquid_list_ >= 0;
  DemArrays a{};
  run("dem_contacts", [&] {
    const Particles& particles = world.particles();
    owned_.rebuild(particles);
    ParticleRange holders = owned_.range();
    if (particles.ghost_count() > 0) {
      holders_.assign(owned_.range().indices, owned_.range().indices + owned_.size());
      for (std::size_t i = particles.owned_size(); i < particles.size(); ++i)
        if (particles.type[i] == ParticleType::Granular && owned_.owns(particles.material[i]))
          holders_.push_back(std::uint32_t(i));
      holders = ParticleRange{holders_.data(), holders_.size()};
    }
    rigid_.clear();
    if (reaction_list_ >= 0)
      for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles.type[i] == ParticleType::Rigid) rigid_.push_back(std::uint32_t(i));
    DemContactList::Sources sources;
    sources.grains = &world.neighbours(grains_list_);
    sources.reactions = reaction_list_ >= 0 ? &world.neighbours(reaction_list_) : nullptr;
    sources.boxes = &world.containers();
    sources.radius = particles[radius_].data();
    sources.skin = skin_;
    if (domain_) contacts_.follow_migration(*domain_);
    contacts_.rebuild(particles, owned_, holders, sources, world.executor());
    // Velocity Verlet (as in LIGGGHTS): kick half, drift, forces at the new positions with the
    // half-step velocities, kick half. The forces are kept in particle fields, so they follow the
    // particles through reordering; the first step computes them first.
    if (liquid) interpolate_fluid(world);
    a = arrays(world);
    a.holders = holders;
    if (!primed_) {
      run_dem_first_forces(world.executor(), a, h_);
      primed_ = true;
    }
  });
  run_dem_substeps(world.executor(), a, dt, n, h_, run);
  if (liquid && world.coupling().active(CouplingArray::LiquidForce))
    run("dem_contacts", [&] { liquid_reactions(world); });
  stats_.iterations = n;
}

void DemSolver::save_state(StateWriter& out) const {
  out.put(std::uint8_t(primed_));
  if (domain_)
    contacts_.save_gathered(out, *domain_);
  else
    contacts_.save_state(out);
}

void DemSolver::restore_state(StateReader& in) {
  primed_ = in.get<std::uint8_t>() != 0;
  contacts_.restore_state(in);
}

void DemSolver::interpolate_fluid(World& world) {
  Particles& p = world.particles();
  fluid_.assign(p.size(), GrainFluidState{});
  std::fill(p[fluid_force_].begin(), p[fluid_force_].end(), Vec3{});
  // Ghosts' positions are current at the step's start: the liquid reads them as they were.
  start_position_.assign(p.position.begin(), p.position.end());
  world.executor().run(
      owned_.range(),
      DemFluidStateStage{view_of(world.neighbours(grain_liquid_list_)),
                         view_of(world.neighbours(grain_voidage_list_)), world.kernel(),
                         p.position.data(), p.velocity.data(), p.mass.data(), p.type.data(),
                         p.material.data(), p[radius_].data(), liquid_density_.data(),
                         liquid_viscosity_.data(), p[fluid_weight_sum_].data(), fluid_.data()});
}

void DemSolver::liquid_reactions(World& world) {
  const Particles& p = world.particles();
  world.executor().run(
      all_particles(p.size()),
      DemLiquidReactionStage{view_of(world.neighbours(liquid_grain_list_)), world.kernel(),
                             start_position_.data(), p.mass.data(), p.type.data(),
                             p.material.data(), liquid_density_.data(), owned_.materials(),
                             p[fluid_weight_sum_].data(), p[fluid_force_].data(),
                             world.coupling()[CouplingArray::LiquidForce].data()});
}

DemArrays DemSolver::arrays(World& world) {
  Particles& p = world.particles();
  DemArrays a{};
  a.model = model_;
  a.contacts = contacts_.view();
  a.pairs = pairs_->table();
  a.owned = owned_.range();
  a.holders = owned_.range();
  a.rigid = ParticleRange{rigid_.data(), rigid_.size()};
  a.x = p.position.data();
  a.v = p.velocity.data();
  a.w = p[angular_velocity_].data();
  a.mass = p.mass.data();
  a.radius = p[radius_].data();
  a.type = p.type.data();
  a.material = p.material.data();
  a.boxes = world.containers().data();
  a.gravity = world.settings().gravity;
  a.fluid = fluid_.empty() ? nullptr : fluid_.data();
  a.fluid_force = fluid_.empty() ? nullptr : p[fluid_force_].data();
  a.force = p[force_].data();
  a.torque = p[torque_].data();
  a.boundary_force =
      reaction_list_ >= 0 ? world.coupling()[CouplingArray::BoundaryForce].data() : nullptr;
  a.wall_normal = p[wall_normal_].data();
  a.wall_shear = p[wall_shear_].data();
  a.contact_load = p[contact_load_].data();
  return a;
}

std::vector<SolverTable> DemSolver::tables(const World& world) const {
  if (world.containers().empty()) return {};
  return {{std::string(name()) + "_walls", container_wall_columns(world.containers().size())}};
}

std::vector<std::vector<double>> DemSolver::table_rows(const World& world,
                                                       const Particles& state) const {
  if (world.containers().empty()) return {};
  // By name, not by handle: `state` may be another copy of the particles. A last good state
  // keeps only the exported fields: no row from it.
  const std::vector<Vec3>* normal = state.find_vector(kWallNormalField);
  const std::vector<Vec3>* shear = state.find_vector(kWallShearField);
  const std::vector<Real>* radius = state.find_scalar(kRadiusField);
  if (!normal || !shear || !radius) return {};
  return {container_wall_row(container_wall_forces(state, world.containers(), owned_.materials(),
                                                   normal->data(), shear->data(), radius->data()))};
}

}  // namespace upf
