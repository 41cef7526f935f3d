// The force between two touching spheres (or a sphere and a wall), written once for host and
// device. Two models:
//
//   Linear spring-dashpot (Cundall & Strack 1979, "A discrete numerical model for granular
//   assemblies", Geotechnique 29(1)): F_n = k_n delta - c_n v_n, with c_n = 2 zeta sqrt(m* k_n)
//   and zeta = -ln e / sqrt(pi^2 + ln^2 e), so a head-on impact rebounds with restitution e after
//   a contact time pi / (omega0 sqrt(1 - zeta^2)), omega0 = sqrt(k_n / m*). The damping is not
//   clipped at the end of the contact, which is what makes e exact.
//
//   Hertz-Mindlin (no-slip), in the form of Tsuji, Tanaka & Ishida 1992 (Powder Technol. 71) as
//   used by LIGGGHTS and EDEM: F_n = 4/3 E* sqrt(R*) delta^(3/2) - 2 sqrt(5/6) beta' sqrt(S_n m*)
//   v_n with S_n = 2 E* sqrt(R* delta), S_t = 8 G* sqrt(R* delta), beta' = -ln e / sqrt(ln^2 e +
//   pi^2); the normal damping is clipped so the pair never pulls (Hertz contacts end at zero
//   force).
//
// Tangential force of both: a spring on the accumulated tangential displacement xi (the contact
// history, kept per pair) plus a dashpot, F_t = -k_t xi - c_t v_t, capped by Coulomb at mu |F_n|
// (the spring is then reset to the capped force, Luding 2008). xi is turned into the current
// tangent plane every step, keeping its length. Rolling resistance: a torque mu_r R* |F_n|
// against the relative rolling (the constant directional torque model, Ai et al. 2011, model A).
//
// Sign conventions: n points from the partner to this particle; v_rel is this particle's
// contact-point velocity relative to the partner's. Every expression is odd in (n, v_rel, xi),
// so the partner computing the same pair gets exactly the opposite force, bit for bit.
#pragma once

#include <cmath>

#include "framework/core/vec3.h"

namespace upf {

enum class DemModel { Linear, Hertz };

// The constants of one pair of materials (or material and wall).
struct DemPairParams {
  Real r_eff = 0;               // R* = R_i R_j / (R_i + R_j), m (R_i for a wall)
  Real m_eff = 0;               // m* = m_i m_j / (m_i + m_j), kg (m_i for a wall)
  Real k_n = 0, k_t = 0;        // linear: spring constants, N/m
  Real c_n = 0, c_t = 0;        // linear: dashpot constants, N s/m
  Real e_star = 0, g_star = 0;  // Hertz: effective Young's and shear moduli, Pa
  Real beta = 0;                // Hertz: 2 sqrt(5/6) (-ln e) / sqrt(ln^2 e + pi^2)
  Real friction = 0, rolling_friction = 0;
  Real cohesion_force = 0;  // N, while touching
};

struct DemContactForce {
  Vec3 force;       // on this particle, N
  Vec3 xi;          // the updated tangential displacement, m
  Real normal = 0;  // |F_n| (elastic + damping), N, for rolling resistance
};

UPF_HD inline Real dem_damping_ratio(Real restitution) {
  const Real l = std::log(restitution);
  return -l / std::sqrt(Real(9.869604401089358) + l * l);
}

// overlap > 0; n unit, from the partner to this particle; v_rel as above; xi the pair's old
// tangential displacement (zero for a new contact).
UPF_HD inline DemContactForce dem_contact_force(DemModel model, const DemPairParams& p,
                                                Real overlap, const Vec3& n, const Vec3& v_rel,
                                                Vec3 xi, Real dt) {
  const Real vn = dot(v_rel, n);
  const Vec3 vt = v_rel - n * vn;
  Real kn, cn, kt, ct;
  Real fn_elastic;
  if (model == DemModel::Linear) {
    kn = p.k_n;
    cn = p.c_n;
    kt = p.k_t;
    ct = p.c_t;
    fn_elastic = kn * overlap;
  } else {
    const Real a = std::sqrt(p.r_eff * overlap);  // contact radius
    const Real sn = Real(2) * p.e_star * a;
    const Real st = Real(8) * p.g_star * a;
    kn = Real(2) / Real(3) * sn;  // F = 4/3 E* sqrt(R*) delta^(3/2) = (2/3 S_n) delta
    fn_elastic = kn * overlap;
    cn = p.beta * std::sqrt(sn * p.m_eff);
    kt = st;
    ct = p.beta * std::sqrt(st * p.m_eff);
  }
  Real fn = fn_elastic - cn * vn;
  if (model == DemModel::Hertz && fn < 0) fn = 0;
  fn -= p.cohesion_force;

  // The old displacement, turned into the current tangent plane with its length kept (one
  // square root: the ratio of the squared lengths).
  const Real xi_len2 = squared_norm(xi);
  if (xi_len2 > 0) {
    xi = xi - n * dot(xi, n);
    const Real xi_new_len2 = squared_norm(xi);
    if (xi_new_len2 > 0) xi = xi * std::sqrt(xi_len2 / xi_new_len2);
  }
  xi += vt * dt;
  Vec3 ft = -(xi * kt) - vt * ct;
  const Real ft_len2 = squared_norm(ft);
  const Real limit = p.friction * std::abs(fn);
  if (ft_len2 > limit * limit) {
    // Sliding: the force at the Coulomb limit, and the spring that would give it.
    ft = ft * (limit / std::sqrt(ft_len2));
    xi = kt > 0 ? -(ft + vt * ct) / kt : Vec3{};
  }
  return {n * fn + ft, xi, std::abs(fn)};
}

// Rolling-resistance torque on this particle: mu_r R* |F_n| against w_rel = w_i - w_j.
UPF_HD inline Vec3 dem_rolling_torque(const DemPairParams& p, Real normal, const Vec3& w_rel) {
  const Real w = norm(w_rel);
  if (w <= 0 || p.rolling_friction <= 0) return {};
  return w_rel * (-p.rolling_friction * p.r_eff * normal / w);
}

}  // namespace upf
