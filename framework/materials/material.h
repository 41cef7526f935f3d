// Materials: what a particle is made of. Each material has a kind (liquid, frozen, ...) that fixes
// its particle type and its parameter table, and names the solver that moves its particles.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/particle_type.h"
#include "framework/params/param_spec.h"
#include "framework/particles/particles.h"

namespace upf {

// A kind of material, registered by materials/: its particle type and its parameters.
struct MaterialKind {
  std::string name;  // "liquid", "frozen", ...
  ParticleType type = ParticleType::Liquid;
  std::string summary;
  std::vector<ParamSpec> params;
  std::string default_solver;  // empty: no solver moves it (frozen)
};

struct Material {
  std::string name;
  std::string kind;
  ParticleType type = ParticleType::Liquid;
  ParamValues params;
  std::string solver;  // empty when nothing moves it
  ParamValues solver_params;
  // Liquids: the surface tension model (scene key "surface_tension_model"; empty: the first one
  // registered) and Akinci's adhesion coefficient toward each named boundary material ("adhesion",
  // or from "contact_angle", whose degrees are kept beside it).
  std::string surface_tension_model;
  std::map<std::string, double> adhesion;
  std::map<std::string, double> contact_angle;

  double param(const std::string& n) const { return params.get(n); }
};

class MaterialTable {
 public:
  MaterialId add(Material m);
  std::size_t size() const { return materials_.size(); }
  const Material& operator[](MaterialId id) const { return materials_.at(id); }
  std::optional<MaterialId> find(const std::string& name) const;
  const std::vector<Material>& all() const { return materials_; }

 private:
  std::vector<Material> materials_;
};

}  // namespace upf
