#include "framework/scene/liquid_mix_keys.h"

#include <sstream>

namespace upf {

namespace {

std::string number(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

std::string density_contrast_solvers(const Registry& registry) {
  std::string list;
  for (const SolverInfo& s : registry.solvers())
    if (s.type == ParticleType::Liquid && s.density_contrast)
      list += (list.empty() ? "" : ", ") + s.name;
  return list.empty() ? "none is registered" : list;
}

}  // namespace

bool liquids_differ_in_density(const SceneDescription& scene) {
  const Material* first = nullptr;
  for (const Material& m : scene.materials) {
    if (m.type != ParticleType::Liquid) continue;
    if (!first) first = &m;
    if (m.param("density") != first->param("density")) return true;
  }
  return false;
}

void check_liquid_mix_keys(JsonInput& in, const Registry& registry, const SceneDescription& scene) {
  for (std::size_t a = 0; a < scene.materials.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      const Material &ma = scene.materials[a], &mb = scene.materials[b];
      if (ma.type != ParticleType::Liquid || mb.type != ParticleType::Liquid) continue;
      const std::string path = "/materials/" + ma.name;
      if (ma.solver != mb.solver) {
        in.problem(path + "/solver",
                   "'" + ma.solver + "' differs from material '" + mb.name + "''s '" + mb.solver +
                       "'; liquids that can meet must share one pressure solve (each solver moves "
                       "only its own particles and would see the other's as mass without "
                       "pressure): name one fluid solver for both");
        continue;
      }
      const double rho_a = ma.param("density"), rho_b = mb.param("density");
      if (rho_a == rho_b) continue;
      const double ratio = rho_a > rho_b ? rho_a / rho_b : rho_b / rho_a;
      const std::string pair = "'" + ma.name + "' (" + number(rho_a) + " kg/m^3) and '" + mb.name +
                               "' (" + number(rho_b) + " kg/m^3)";
      if (ratio > kMaxLiquidDensityRatio)
        in.problem(path + "/density",
                   "the rest densities of " + pair + " differ by a ratio of " + number(ratio) +
                       ", above " + number(kMaxLiquidDensityRatio) +
                       ", the largest the interface method (Solenthaler & Pajarola 2008) holds");
      const SolverInfo* solver = registry.find_solver(ma.solver);
      if (solver && !solver->density_contrast)
        in.problem(path + "/solver",
                   "solver '" + ma.solver +
                       "' sums densities over neighbours' masses and cannot "
                       "hold liquids of different rest density at an interface (" +
                       pair + "); solvers that can: " + density_contrast_solvers(registry));
    }
}

}  // namespace upf
