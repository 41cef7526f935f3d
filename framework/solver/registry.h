// The registry: solvers, material kinds and scene-file sections by name. An application builds one,
// registers the built-in pieces and any plug-ins, and hands it to scene loading. No global registry
// exists: several registries (and worlds) can live in one process.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/materials/material.h"
#include "framework/params/param_spec.h"
#include "framework/scene/scene_section.h"
#include "framework/solver/solver.h"
#include "framework/world/coupling.h"

namespace upf {

struct SolverInfo {
  std::string name;  // as written in scene files: "pcisph"
  ParticleType type = ParticleType::Liquid;
  std::string summary;
  std::string reference;  // the paper
  std::vector<ParamSpec> params;
  // Creates the solver that moves the particles of `materials` with parameters `values`.
  std::function<std::unique_ptr<Solver>(const ParamValues& values,
                                        std::vector<MaterialId> materials)>
      create;
  // The coupling arrays the solver writes and reads (framework/world/coupling.h): the world
  // orders solvers by them and refuses a scene whose reads nobody writes.
  CouplingUse coupling;
  // Liquids only: the solver holds liquids of different rest density at one interface (the
  // number-density forms of solvers/fluid/density_contrast.h); a scene that mixes densities under
  // a solver without it is refused.
  bool density_contrast = false;
};

// A surface tension model the liquids may name (scene key "surface_tension_model"); the shared
// fluid pieces implement it (solvers/fluid/surface_forces.h). The first registered is the default.
struct SurfaceTensionModelInfo {
  std::string name;  // "akinci2013"
  std::string summary;
  std::string reference;  // the paper
  // The model pulls liquid toward walls and bodies by the liquid's "adhesion" (Akinci's adhesion,
  // solvers/fluid/surface_forces.h); a scene that asks a model without it for wetting is refused.
  bool adhesion = true;
};

class Registry {
 public:
  void add_solver(SolverInfo info);
  void add_surface_tension_model(SurfaceTensionModelInfo info);
  void add_material_kind(MaterialKind kind);
  void add_scene_section(SceneSection section);

  const SolverInfo* find_solver(const std::string& name) const;
  const MaterialKind* find_material_kind(const std::string& name) const;
  const std::vector<SolverInfo>& solvers() const { return solvers_; }
  const std::vector<MaterialKind>& material_kinds() const { return kinds_; }
  const std::vector<SurfaceTensionModelInfo>& surface_tension_models() const {
    return surface_models_;
  }
  const SceneSection* find_scene_section(const std::string& key) const;
  const std::vector<SceneSection>& scene_sections() const { return sections_; }

 private:
  std::vector<SolverInfo> solvers_;
  std::vector<MaterialKind> kinds_;
  std::vector<SceneSection> sections_;
  std::vector<SurfaceTensionModelInfo> surface_models_;
};

}  // namespace upf
