// The per-particle stages of the DEM solver (dem_solver.h): contact forces, the pair forces'
// gather, the reactions on rigid particles, velocity Verlet's kick and drift, and the coupling with
// liquid (the fluid state at each grain, and the grains' force on the liquid). Plain structs of
// views with a UPF_HD operator()(i) that writes only particle i's outputs (and the candidates it
// holds). C++17.
#pragma once

#include <cmath>
#include <cstdint>

#include "framework/kernels/cubic_spline.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/world/container_box.h"
#include "solvers/dem/dem_contact.h"
#include "solvers/dem/dem_fluid_drag.h"
#include "solvers/dem/dem_views.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

inline constexpr Real kDemBallVolume = Real(4.0 / 3.0 * 3.14159265358979323846);

// What DemForcesStage records for export (dem_wall_forces.h): the container walls' forces on each
// grain averaged over the world step. Null pointers: not recorded.
struct DemContactRecord {
  // Per grain: the normal forces of container faces on it, by axis (a face on the lower side of
  // an axis pushes +, one on the upper side -), and the faces' tangential forces, both averaged
  // over the step's sub-steps.
  Vec3* wall_normal = nullptr;
  Vec3* wall_shear = nullptr;
  Real weight = 0;       // this sub-step's share of the step (h / dt)
  bool restart = false;  // the step's first sub-step: the averages start again
};

// Contact, gravity and fluid forces on grain i at the current state, with the springs of its
// candidates updated; the fluid force is added to the step's average with weight fluid_weight.
struct DemForcesStage {
  DemModel model;
  DemContactView contacts;
  DemPairTable pairs;
  const Vec3* x;
  const Vec3* v;
  const Vec3* w;
  const Real* m;
  const Real* radius;
  const ParticleType* type;
  const MaterialId* mat;
  const ContainerBox* boxes;
  Vec3 gravity;
  Real h;                        // the sub-step, s
  Real t_in_step;                // time since the world step began, s
  const GrainFluidState* fluid;  // null without liquid
  Real fluid_weight;
  Vec3* fluid_force;
  Vec3* force;
  Vec3* torque;
  DemContactRecord record;

  UPF_HD void operator()(std::uint32_t i) const {
    const Real ri = radius[i];
    Vec3 f = gravity * m[i];
    Vec3 tau{};
    Vec3 wall_normal{}, wall_shear{};
    bool walled = false;
    for (std::uint32_t k = contacts.offsets[i]; k < contacts.offsets[i + 1]; ++k) {
      const std::uint32_t j = contacts.partner[k];
      if (j & kDemWallPartner) {
        walled = wall(i, k, j & ~kDemWallPartner, f, tau, wall_normal, wall_shear) || walled;
      } else {
        sphere(i, k, j, f, tau);
      }
    }
    // Most grains touch no wall: they write their averages only when those start again.
    if (record.wall_normal && record.restart) {
      record.wall_normal[i] = wall_normal * record.weight;
      record.wall_shear[i] = wall_shear * record.weight;
    } else if (record.wall_normal && walled) {
      record.wall_normal[i] += wall_normal * record.weight;
      record.wall_shear[i] += wall_shear * record.weight;
    }
    if (fluid && fluid[i].fluid_fraction > 0) {
      const Real volume = kDemBallVolume * ri * ri * ri;
      const Vec3 from_fluid =
          di_felice_drag(fluid[i], ri, v[i]) + grain_buoyancy(fluid[i], volume, gravity);
      f += from_fluid;
      fluid_force[i] += from_fluid * fluid_weight;
    }
    force[i] = f;
    torque[i] = tau;
  }

 private:
  // A force at contact k: on i, with its torque; the partner's torque recorded on the candidate.
  // r_partner: the partner's radius, for the torque it gets back (DemGatherPairsStage). Returns
  // the contact's force on i.
  UPF_INLINE UPF_HD Vec3 apply(std::uint32_t i, std::uint32_t k, const DemPairParams& pp,
                               Real overlap, const Vec3& n, const Vec3& v_rel, const Vec3& w_rel,
                               Real r_partner, Vec3& f, Vec3& tau) const {
    const DemContactForce c = dem_contact_force(model, pp, overlap, n, v_rel, contacts.xi[k], h);
    f += c.force;
    // The tangential force acts at the contact point, -R_i n from the centre.
    const Vec3 rolling = dem_rolling_torque(pp, c.normal, w_rel);
    const Vec3 tangential = c.force - n * dot(c.force, n);
    tau += cross(n * (-radius[i]), tangential);
    tau += rolling;
    contacts.touch(k, c.xi, c.force, cross(n * r_partner, -tangential), rolling);
    return c.force;
  }

  // Grain i against sphere j: another grain, or a body's boundary particle moving on at its
  // step-start velocity. The partner's velocity and spin are read only for a touching pair: most
  // candidates are apart.
  UPF_INLINE UPF_HD void sphere(std::uint32_t i, std::uint32_t k, std::uint32_t j, Vec3& f,
                                Vec3& tau) const {
    const bool grain = type[j] == ParticleType::Granular;
    const Real ri = radius[i];
    const Real rj = grain ? radius[j] : pairs.boundary_radius;
    const Vec3 d = grain ? x[i] - x[j] : x[i] - (x[j] + v[j] * t_in_step);
    const Real reach = ri + rj;
    const Real d2 = squared_norm(d);
    if (d2 >= reach * reach || d2 <= 0) {
      contacts.separate(k);
      return;
    }
    const Real dist = std::sqrt(d2);
    const Vec3 n = d / dist;
    const Vec3 spin = grain ? w[i] * ri + w[j] * rj : w[i] * ri;
    const Vec3 w_rel = grain ? w[i] - w[j] : w[i];
    const DemPairParams& pp = grain ? pairs.pair(mat[i], mat[j]) : pairs.boundary[mat[i]];
    apply(i, k, pp, reach - dist, n, v[i] - v[j] - cross(spin, n), w_rel, rj, f, tau);
  }

  // A container face (code = container * 6 + face), if the grain is inside the box (or within a
  // radius of it). The face's force splits into its normal part (axis a) and the rest. Returns
  // whether they touch.
  UPF_INLINE UPF_HD bool wall(std::uint32_t i, std::uint32_t k, std::uint32_t code, Vec3& f,
                              Vec3& tau, Vec3& wall_normal, Vec3& wall_shear) const {
    const Real ri = radius[i];
    const ContainerBox& box = boxes[code / 6];
    bool inside = true;
    for (int a = 0; a < 3; ++a)
      inside = inside && x[i][a] > box.min[a] - ri && x[i][a] < box.max[a] + ri;
    const int a = int(code % 6) / 2;
    const bool lower = code % 2 == 0;
    const Real overlap = ri - (lower ? x[i][a] - box.min[a] : box.max[a] - x[i][a]);
    if (!inside || overlap <= 0) {
      contacts.separate(k);
      return false;
    }
    Vec3 n{};
    n[a] = lower ? Real(1) : Real(-1);
    Vec3 on_grain =
        apply(i, k, pairs.walls[mat[i]], overlap, n, v[i] - cross(w[i] * ri, n), w[i], 0, f, tau);
    wall_normal[a] += on_grain[a];
    on_grain[a] = 0;
    wall_shear += on_grain;
    return true;
  }
};

// Adds to grain j the opposite of the pair forces its lower-id partners computed.
struct DemGatherPairsStage {
  DemContactView contacts;
  Vec3* force;
  Vec3* torque;
  UPF_HD void operator()(std::uint32_t j) const {
    Vec3 f = force[j], tau = torque[j];
    for (std::uint32_t r = contacts.reverse_offsets[j]; r < contacts.reverse_offsets[j + 1]; ++r) {
      const std::uint32_t k = contacts.reverse[r];
      if (!contacts.touching[k]) continue;
      f -= contacts.force[k];
      tau += contacts.partner_torque[k];
      tau -= contacts.partner_rolling[k];
    }
    force[j] = f;
    torque[j] = tau;
  }
};

// Grain i's contact load: the sum of |F| over its touching contacts, those it holds and those
// its partners hold (the same forces DemForcesStage and DemGatherPairsStage applied).
struct DemContactLoadStage {
  DemContactView contacts;
  Real* contact_load;
  UPF_HD void operator()(std::uint32_t i) const {
    Real load = 0;
    for (std::uint32_t k = contacts.offsets[i]; k < contacts.offsets[i + 1]; ++k)
      if (contacts.touching[k]) load += norm(contacts.force[k]);
    for (std::uint32_t r = contacts.reverse_offsets[i]; r < contacts.reverse_offsets[i + 1]; ++r)
      if (contacts.touching[contacts.reverse[r]]) load += norm(contacts.force[contacts.reverse[r]]);
    contact_load[i] = load;
  }
};

// Adds to rigid particle b the sub-step's contact forces of grains on it, times `weight`.
struct DemBoundaryReactionStage {
  DemContactView contacts;
  Real weight;
  Vec3* reaction;
  UPF_HD void operator()(std::uint32_t b) const {
    Vec3 sum{};
    for (std::uint32_t q = contacts.reverse_offsets[b]; q < contacts.reverse_offsets[b + 1]; ++q) {
      const std::uint32_t k = contacts.reverse[q];
      if (contacts.touching[k]) sum -= contacts.force[k];
    }
    reaction[b] += sum * weight;
  }
};

// Velocity Verlet: v += F h_kick / m, w += tau h_kick / I, then x += v h_drift.
struct DemKickDriftStage {
  const Vec3* force;
  const Vec3* torque;
  const Real* m;
  const Real* radius;
  Real h_kick, h_drift;
  Vec3* x;
  Vec3* v;
  Vec3* w;
  UPF_HD void operator()(std::uint32_t i) const {
    // The moment of inertia of a solid sphere is 0.4 m R^2.
    v[i] += force[i] * (h_kick / m[i]);
    w[i] += torque[i] * (h_kick / (Real(0.4) * m[i] * radius[i] * radius[i]));
    if (h_drift > 0) x[i] += v[i] * h_drift;
  }
};

// The liquid around grain i: Shepard averages of the fluid fraction, velocity, density and
// viscosity, and the voidage (one minus the grains' volume fraction, this grain included).
struct DemFluidStateStage {
  NeighbourView liquid;  // grain -> liquid
  NeighbourView grains;  // grain -> grains, over the kernel support
  CubicSplineKernel kernel;
  const Vec3* x;
  const Vec3* v;
  const Real* m;
  const ParticleType* type;
  const MaterialId* mat;
  const Real* radius;
  const Real* liquid_density;    // by material
  const Real* liquid_viscosity;  // by material
  Real* weight_sum;
  GrainFluidState* fluid;

  UPF_HD void operator()(std::uint32_t i) const {
    Real phi = 0, rho = 0, mu = 0;
    Vec3 u{};
    for (std::uint32_t k = liquid.offsets[i]; k < liquid.offsets[i + 1]; ++k) {
      const std::uint32_t j = liquid.indices[k];
      const Real rho0 = liquid_density[mat[j]];
      const Real wj = m[j] / rho0 * kernel.value(x[i] - x[j]);
      phi += wj;
      u += v[j] * wj;
      rho += rho0 * wj;
      mu += liquid_viscosity[mat[j]] * wj;
    }
    weight_sum[i] = phi;
    if (phi <= 0) return;
    Real solid = kDemBallVolume * radius[i] * radius[i] * radius[i] * kernel.value(Real(0));
    for (std::uint32_t k = grains.offsets[i]; k < grains.offsets[i + 1]; ++k) {
      const std::uint32_t j = grains.indices[k];
      if (type[j] != ParticleType::Granular) continue;
      solid += kDemBallVolume * radius[j] * radius[j] * radius[j] * kernel.value(x[i] - x[j]);
    }
    GrainFluidState& s = fluid[i];
    s.fluid_velocity = u / phi;
    s.fluid_density = rho / phi;
    s.fluid_viscosity = mu / phi;
    // std::min and std::clamp, spelt out for device code.
    s.fluid_fraction = Real(1) < phi ? Real(1) : phi;
    const Real voidage = Real(1) - solid;
    s.voidage = voidage < Real(0.1) ? Real(0.1) : (Real(1) < voidage ? Real(1) : voidage);
  }
};

// The grains' fluid force on liquid particle j: each grain's force shared among its liquid
// neighbours by their Shepard weights, which sum to one, so the liquid gets exactly the opposite
// of what the grains got. Weights at the step-start positions x0, the ones weight_sum was made
// with.
struct DemLiquidReactionStage {
  NeighbourView grains;  // liquid -> grains
  CubicSplineKernel kernel;
  const Vec3* x0;
  const Real* m;
  const ParticleType* type;
  const MaterialId* mat;
  const Real* liquid_density;  // by material
  OwnedMaterials owns;
  const Real* weight_sum;
  const Vec3* fluid_force;
  Vec3* out;

  UPF_HD void operator()(std::uint32_t j) const {
    if (type[j] != ParticleType::Liquid) return;
    Vec3 f{};
    const Real vj = m[j] / liquid_density[mat[j]];
    for (std::uint32_t k = grains.offsets[j]; k < grains.offsets[j + 1]; ++k) {
      const std::uint32_t i = grains.indices[k];
      if (!owns(mat[i]) || weight_sum[i] <= 0) continue;
      f -= fluid_force[i] * (vj * kernel.value(x0[j] - x0[i]) / weight_sum[i]);
    }
    out[j] = f;
  }
};

}  // namespace upf
