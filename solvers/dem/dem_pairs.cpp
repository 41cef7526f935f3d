#include "solvers/dem/dem_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace upf {

namespace {
constexpr double kPi = 3.14159265358979323846;

double hertz_beta(double e) {
  const double l = std::log(e);
  return 2.0 * std::sqrt(5.0 / 6.0) * (-l) / std::sqrt(l * l + kPi * kPi);
}
}  // namespace

DemPairs::DemPairs(const MaterialTable& materials, Real spacing)
    : n_(materials.size()), boundary_radius_(Real(0.5) * spacing) {
  grains_.resize(n_);
  for (std::size_t m = 0; m < n_; ++m) {
    const Material& mat = materials[MaterialId(m)];
    if (mat.type != ParticleType::Granular) continue;
    DemGrainMaterial& g = grains_[m];
    g.granular = true;
    g.radius = Real(mat.param("radius") > 0 ? mat.param("radius") : 0.5 * double(spacing));
    g.density = Real(mat.param("density"));
    g.mass = Real(mat.param("density") * 4.0 / 3.0 * kPi * std::pow(double(g.radius), 3));
    g.youngs = Real(mat.param("youngs_modulus"));
    g.poisson = Real(mat.param("poisson_ratio"));
    g.k_n = Real(mat.param("normal_stiffness"));
    g.restitution = Real(mat.param("restitution"));
    g.friction = Real(mat.param("friction"));
    g.wall_friction =
        mat.param("wall_friction") >= 0 ? Real(mat.param("wall_friction")) : g.friction;
    g.rolling_friction = Real(mat.param("rolling_friction"));
    g.cohesion = Real(mat.param("cohesion"));
  }
  pairs_.resize(n_ * n_);
  walls_.resize(n_);
  boundary_.resize(n_);
  for (std::size_t a = 0; a < n_; ++a) {
    if (!grains_[a].granular) continue;
    walls_[a] = make(grains_[a], nullptr, 0, true);
    boundary_[a] = make(grains_[a], nullptr, boundary_radius_, true);
    for (std::size_t b = 0; b < n_; ++b)
      if (grains_[b].granular) pairs_[a * n_ + b] = make(grains_[a], &grains_[b], 0, false);
  }
}

DemPairParams DemPairs::make(const DemGrainMaterial& a, const DemGrainMaterial* b, Real r_other,
                             bool rigid_other) const {
  DemPairParams p;
  const double ra = a.radius, ma = a.mass;
  const double rb = b ? double(b->radius) : double(r_other);
  p.r_eff = Real(rb > 0 ? ra * rb / (ra + rb) : ra);
  p.m_eff = Real(b && !rigid_other ? ma * b->mass / (ma + b->mass) : ma);
  const auto mean = [&](Real x, Real y) { return b ? Real(0.5) * (x + y) : x; };
  const double e = mean(a.restitution, b ? b->restitution : 0);
  p.friction = b ? mean(a.friction, b->friction) : a.wall_friction;
  p.rolling_friction = mean(a.rolling_friction, b ? b->rolling_friction : 0);
  const double gamma = mean(a.cohesion, b ? b->cohesion : 0);
  p.cohesion_force = Real(2.0 * kPi * double(p.r_eff) * gamma);

  // Linear: k_n in series for two materials (two springs meeting at the contact).
  const double kn = b ? 1.0 / (1.0 / a.k_n + 1.0 / b->k_n) * 2.0 : a.k_n;
  const double nu = b ? 0.5 * (a.poisson + b->poisson) : a.poisson;
  const double zeta = dem_damping_ratio(Real(e));
  p.k_n = Real(kn);
  p.k_t = Real(kn * 2.0 * (1.0 - nu) / (2.0 - nu));
  p.c_n = Real(2.0 * zeta * std::sqrt(double(p.m_eff) * kn));
  p.c_t = Real(2.0 * zeta * std::sqrt(double(p.m_eff) * double(p.k_t)));

  // Hertz-Mindlin effective moduli; a rigid partner adds nothing.
  double inv_e = (1.0 - a.poisson * a.poisson) / a.youngs;
  double inv_g = 2.0 * (2.0 - a.poisson) * (1.0 + a.poisson) / a.youngs;
  if (b) {
    inv_e += (1.0 - b->poisson * b->poisson) / b->youngs;
    inv_g += 2.0 * (2.0 - b->poisson) * (1.0 + b->poisson) / b->youngs;
  }
  p.e_star = Real(1.0 / inv_e);
  p.g_star = Real(1.0 / inv_g);
  p.beta = Real(hertz_beta(e));
  return p;
}

Real DemPairs::shortest_contact_time(DemModel model) const {
  double t = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < n_; ++a) {
    const DemGrainMaterial& g = grains_[a];
    if (!g.granular) continue;
    if (model == DemModel::Hertz) {
      const double shear = g.youngs / (2.0 * (1.0 + g.poisson));
      t = std::min(t,
                   kPi * g.radius * std::sqrt(g.density / shear) / (0.1631 * g.poisson + 0.8766));
      continue;
    }
    for (std::size_t b = 0; b < n_; ++b) {
      if (!grains_[b].granular) continue;
      for (const DemPairParams* p : {&pairs_[a * n_ + b], &walls_[a], &boundary_[a]}) {
        const double omega0 = std::sqrt(double(p->k_n) / double(p->m_eff));
        const double zeta = double(p->c_n) / (2.0 * std::sqrt(double(p->m_eff * p->k_n)));
        t = std::min(t, kPi / (omega0 * std::sqrt(1.0 - zeta * zeta)));
      }
    }
  }
  return Real(t);
}

}  // namespace upf
