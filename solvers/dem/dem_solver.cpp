#include "solvers/dem/dem_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/stopwatch.h"
#include "framework/world/world.h"

namespace upf {

namespace {

constexpr TypeMask kGranularMask = mask_of(ParticleType::Granular);

// The moment of inertia of a solid sphere over its mass and radius squared.
constexpr Real kSphereInertia = Real(0.4);
// Contact lists reach this many spacings beyond the longest contact distance, and a world step
// lets no grain move more than half of it, so no contact starts unlisted. Short lists are most
// of the DEM's speed: at 0.2, a grain of half a spacing has about 7 candidates, not 33.
constexpr Real kSkinPerSpacing = Real(0.2);

}  // namespace

std::vector<ParamSpec> DemSolver::param_specs() {
  return {
      {"substep_fraction", "1", 0.05, 1e-4, 0.5,
       "DEM sub-step as a fraction of the shortest contact time (linear: the contact time; "
       "Hertz: the Rayleigh time)"},
  };
}

DemSolver::DemSolver(DemModel model, const ParamValues& params, std::vector<MaterialId> materials)
    : model_(model),
      substep_fraction_(params.get("substep_fraction")),
      materials_(std::move(materials)) {}

void DemSolver::prepare(World& world) {
  Particles& p = world.particles();
  owned_.set_materials(world.materials().size(), materials_);
  pairs_ = std::make_unique<DemPairs>(world.materials(), world.settings().spacing);
  substep_ = Real(substep_fraction_) * pairs_->shortest_contact_time(model_);

  std::vector<Real>& radius = p.scalar_field(kRadiusField, 0, true);
  p.vector_field(kAngularVelocityField, {}, true);
  p.vector_field(kForceField);
  p.vector_field(kTorqueField);
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
  // half of it.
  const Particles& p = world.particles();
  Real fastest = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.type[i] == ParticleType::Granular && owned_.owns(p.material[i]))
      fastest = std::max(fastest, norm(p.velocity[i]));
  if (fastest <= 0) return std::numeric_limits<Real>::max();
  return Real(0.5) * skin_ / fastest;
}

void DemSolver::step(World& world, Real dt) {
  Stopwatch watch;
  stats_ = SolverStats{};
  const int n = std::max(1, int(std::ceil(double(dt) / double(substep_) - 1e-9)));
  h_ = dt / Real(n);
  const Particles& particles = world.particles();
  owned_.rebuild(particles);
  rigid_.clear();
  if (reaction_list_ >= 0)
    for (std::size_t i = 0; i < particles.size(); ++i)
      if (particles.type[i] == ParticleType::Rigid) rigid_.push_back(std::uint32_t(i));
  DemContactList::Sources sources;
  sources.grains = &world.neighbours(grains_list_);
  sources.reactions = reaction_list_ >= 0 ? &world.neighbours(reaction_list_) : nullptr;
  sources.boxes = &world.containers();
  sources.radius = particles.find_scalar(kRadiusField)->data();
  sources.skin = skin_;
  contacts_.rebuild(particles, owned_, sources, world.executor());
  double contacts_ms = 0, integrate_ms = 0;
  // Velocity Verlet (as in LIGGGHTS): kick half, drift, forces at the new positions with the
  // half-step velocities, kick half. The forces are kept in particle fields, so they follow the
  // particles through reordering; the first step computes them first.
  const bool liquid = grain_liquid_list_ >= 0;
  if (liquid) interpolate_fluid(world);
  if (!primed_) {
    substep_forces(world, 0, 0);
    gather_pairs(world);
    primed_ = true;
  }
  for (int k = 0; k < n; ++k) {
    kick_drift(world, Real(0.5) * h_, h_);
    integrate_ms += watch.lap_ms();
    substep_forces(world, Real(k + 1) * h_, h_ / dt);
    gather_pairs(world);
    if (reaction_list_ >= 0) substep_reactions(world, h_ / dt);
    contacts_ms += watch.lap_ms();
    kick_drift(world, Real(0.5) * h_, 0);
    integrate_ms += watch.lap_ms();
  }
  if (liquid && world.coupling().active(CouplingArray::LiquidForce)) liquid_reactions(world);
  stats_.iterations = n;
  stats_.stage_ms = {{"dem_contacts", contacts_ms}, {"dem_integration", integrate_ms}};
}

void DemSolver::save_state(StateWriter& out) const {
  out.put(std::uint8_t(primed_));
  contacts_.save_state(out);
}

void DemSolver::restore_state(StateReader& in) {
  primed_ = in.get<std::uint8_t>() != 0;
  contacts_.restore_state(in);
}

void DemSolver::interpolate_fluid(World& world) {
  const Particles& p = world.particles();
  const NeighbourList& liquid = world.neighbours(grain_liquid_list_);
  const NeighbourList& grains = world.neighbours(grain_voidage_list_);
  const CubicSplineKernel kernel = world.kernel();
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  const Real* m = p.mass.data();
  const ParticleType* type = p.type.data();
  const MaterialId* mat = p.material.data();
  const Real* radius = p.find_scalar(kRadiusField)->data();
  fluid_.assign(p.size(), GrainFluidState{});
  fluid_weight_sum_.assign(p.size(), 0);
  fluid_force_.assign(p.size(), Vec3{});
  start_position_.assign(p.position.begin(), p.position.end());
  constexpr Real kBallVolume = Real(4.0 / 3.0 * 3.14159265358979323846);
  owned_.for_each(world.executor(), [&](std::uint32_t i) {
    // Fluid fraction, velocity, density and viscosity: Shepard averages over the liquid.
    Real phi = 0, rho = 0, mu = 0;
    Vec3 u{};
    for (std::uint32_t k = liquid.offsets[i]; k < liquid.offsets[i + 1]; ++k) {
      const std::uint32_t j = liquid.indices[k];
      const Real rho0 = liquid_density_[mat[j]];
      const Real w = m[j] / rho0 * kernel.value(x[i] - x[j]);
      phi += w;
      u += v[j] * w;
      rho += rho0 * w;
      mu += liquid_viscosity_[mat[j]] * w;
    }
    fluid_weight_sum_[i] = phi;
    if (phi <= 0) return;
    // Voidage: one minus the grains' volume fraction, this grain included.
    Real solid = kBallVolume * radius[i] * radius[i] * radius[i] * kernel.value(Real(0));
    for (std::uint32_t k = grains.offsets[i]; k < grains.offsets[i + 1]; ++k) {
      const std::uint32_t j = grains.indices[k];
      if (type[j] != ParticleType::Granular) continue;
      solid += kBallVolume * radius[j] * radius[j] * radius[j] * kernel.value(x[i] - x[j]);
    }
    GrainFluidState& s = fluid_[i];
    s.fluid_velocity = u / phi;
    s.fluid_density = rho / phi;
    s.fluid_viscosity = mu / phi;
    s.fluid_fraction = std::min(phi, Real(1));
    s.voidage = std::clamp(Real(1) - solid, Real(0.1), Real(1));
  });
}

void DemSolver::liquid_reactions(World& world) {
  Particles& p = world.particles();
  const NeighbourList& grains = world.neighbours(liquid_grain_list_);
  const CubicSplineKernel kernel = world.kernel();
  // Weights at the step-start positions, the ones fluid_weight_sum_ was made with.
  const Vec3* x = start_position_.data();
  const Real* m = p.mass.data();
  const ParticleType* type = p.type.data();
  const MaterialId* mat = p.material.data();
  Vec3* out = world.coupling()[CouplingArray::LiquidForce].data();
  // Each grain's force is shared among its liquid neighbours by their Shepard weights, which
  // sum to one: the liquid gets exactly the opposite of what the grains got.
  world.executor().for_each(p.size(), [&](std::size_t j) {
    if (type[j] != ParticleType::Liquid) return;
    Vec3 f{};
    const Real vj = m[j] / liquid_density_[mat[j]];
    for (std::uint32_t k = grains.offsets[j]; k < grains.offsets[j + 1]; ++k) {
      const std::uint32_t i = grains.indices[k];
      if (!owned_.owns(mat[i]) || fluid_weight_sum_[i] <= 0) continue;
      f -= fluid_force_[i] * (vj * kernel.value(x[j] - x[i]) / fluid_weight_sum_[i]);
    }
    out[j] = f;
  });
}

void DemSolver::substep_forces(World& world, Real t_in_step, Real fluid_weight) {
  Particles& p = world.particles();
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  const Real* m = p.mass.data();
  const ParticleType* type = p.type.data();
  const MaterialId* mat = p.material.data();
  const Real* radius = p.find_scalar(kRadiusField)->data();
  const Vec3* w = p.find_vector(kAngularVelocityField)->data();
  const Vec3 g = world.settings().gravity;
  const std::vector<ContainerBox>& boxes = world.containers();
  const Real rb = pairs_->boundary_radius();
  const Real h = h_;
  Vec3* force = p.find_vector(kForceField)->data();
  Vec3* torque = p.find_vector(kTorqueField)->data();

  owned_.for_each(world.executor(), [&](std::uint32_t i) {
    const Real ri = radius[i];
    Vec3 f = g * m[i];
    Vec3 tau{};
    // r_partner: the partner's radius, for the torque it gets back (gather_pairs).
    auto contact = [&](std::uint32_t k, const DemPairParams& pp, Real overlap, const Vec3& n,
                       const Vec3& v_rel, const Vec3& w_rel, Real r_partner) {
      const DemContactForce c =
          dem_contact_force(model_, pp, overlap, n, v_rel, contacts_.xi(k), h);
      f += c.force;
      // The tangential force acts at the contact point, -R_i n from the centre.
      const Vec3 rolling = dem_rolling_torque(pp, c.normal, w_rel);
      const Vec3 tangential = c.force - n * dot(c.force, n);
      tau += cross(n * (-ri), tangential);
      tau += rolling;
      contacts_.touch(k, c.xi, c.force, cross(n * r_partner, -tangential), rolling);
    };

    for (std::uint32_t k = contacts_.begin(i); k < contacts_.end(i); ++k) {
      const std::uint32_t j = contacts_.partner(k);
      if (j & kDemWallPartner) {
        // A container face, if the grain is inside the box (or within a radius of it).
        const std::uint32_t code = j & ~kDemWallPartner;
        const ContainerBox& box = boxes[code / 6];
        bool inside = true;
        for (int a = 0; a < 3; ++a)
          inside = inside && x[i][a] > box.min[a] - ri && x[i][a] < box.max[a] + ri;
        const int a = int(code % 6) / 2;
        const bool lower = code % 2 == 0;
        const Real overlap = ri - (lower ? x[i][a] - box.min[a] : box.max[a] - x[i][a]);
        if (!inside || overlap <= 0) {
          contacts_.separate(k);
          continue;
        }
        Vec3 n{};
        n[a] = lower ? Real(1) : Real(-1);
        const Vec3 v_rel = v[i] - cross(w[i] * ri, n);
        contact(k, pairs_->wall(mat[i]), overlap, n, v_rel, w[i], 0);
      } else if (type[j] == ParticleType::Granular) {
        const Vec3 d = x[i] - x[j];
        const Real reach = ri + radius[j];
        const Real d2 = squared_norm(d);
        if (d2 >= reach * reach || d2 <= 0) {
          contacts_.separate(k);
          continue;
        }
        const Real dist = std::sqrt(d2);
        const Real overlap = reach - dist;
        const Vec3 n = d / dist;
        const Vec3 v_rel = v[i] - v[j] - cross(w[i] * ri + w[j] * radius[j], n);
        contact(k, pairs_->pair(mat[i], mat[j]), overlap, n, v_rel, w[i] - w[j], radius[j]);
      } else {
        // A body's boundary particle, moving on at its step-start velocity.
        const Vec3 d = x[i] - (x[j] + v[j] * t_in_step);
        const Real reach = ri + rb;
        const Real d2 = squared_norm(d);
        if (d2 >= reach * reach || d2 <= 0) {
          contacts_.separate(k);
          continue;
        }
        const Real dist = std::sqrt(d2);
        const Real overlap = reach - dist;
        const Vec3 n = d / dist;
        const Vec3 v_rel = v[i] - v[j] - cross(w[i] * ri, n);
        contact(k, pairs_->boundary(mat[i]), overlap, n, v_rel, w[i], rb);
      }
    }
    if (!fluid_.empty() && fluid_[i].fluid_fraction > 0) {
      const Real volume = Real(4.0 / 3.0 * 3.14159265358979323846) * ri * ri * ri;
      const Vec3 fluid = di_felice_drag(fluid_[i], ri, v[i]) + grain_buoyancy(fluid_[i], volume, g);
      f += fluid;
      fluid_force_[i] += fluid * fluid_weight;
    }
    force[i] = f;
    torque[i] = tau;
  });
}

void DemSolver::gather_pairs(World& world) {
  Particles& p = world.particles();
  Vec3* force = p.find_vector(kForceField)->data();
  Vec3* torque = p.find_vector(kTorqueField)->data();
  owned_.for_each(world.executor(), [&](std::uint32_t j) {
    Vec3 f = force[j], tau = torque[j];
    for (std::uint32_t r = contacts_.reverse_begin(j); r < contacts_.reverse_end(j); ++r) {
      const std::uint32_t k = contacts_.reverse_pair(r);
      if (!contacts_.touching(k)) continue;
      f -= contacts_.force(k);
      tau += contacts_.partner_torque(k);
      tau -= contacts_.partner_rolling(k);
    }
    force[j] = f;
    torque[j] = tau;
  });
}

void DemSolver::substep_reactions(World& world, Real weight) {
  Vec3* reaction = world.coupling()[CouplingArray::BoundaryForce].data();
  const std::uint32_t* rigid = rigid_.data();
  world.executor().for_each(rigid_.size(), [&](std::size_t r) {
    const std::uint32_t b = rigid[r];
    Vec3 sum{};
    for (std::uint32_t q = contacts_.reverse_begin(b); q < contacts_.reverse_end(b); ++q) {
      const std::uint32_t k = contacts_.reverse_pair(q);
      if (contacts_.touching(k)) sum -= contacts_.force(k);
    }
    reaction[b] += sum * weight;
  });
}

void DemSolver::kick_drift(World& world, Real h_kick, Real h_drift) {
  Particles& p = world.particles();
  Vec3* x = p.position.data();
  Vec3* v = p.velocity.data();
  Vec3* w = p.vector_field(kAngularVelocityField).data();
  const Vec3* f = p.find_vector(kForceField)->data();
  const Vec3* tau = p.find_vector(kTorqueField)->data();
  const Real* m = p.mass.data();
  const Real* radius = p.find_scalar(kRadiusField)->data();
  owned_.for_each(world.executor(), [&](std::uint32_t i) {
    v[i] += f[i] * (h_kick / m[i]);
    w[i] += tau[i] * (h_kick / (kSphereInertia * m[i] * radius[i] * radius[i]));
    if (h_drift > 0) x[i] += v[i] * h_drift;
  });
}

}  // namespace upf
