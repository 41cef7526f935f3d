#include "framework/solver/registry.h"

#include <stdexcept>

namespace upf {

void Registry::add_solver(SolverInfo info) {
  if (find_solver(info.name)) throw std::logic_error("solver '" + info.name + "' registered twice");
  solvers_.push_back(std::move(info));
}

void Registry::add_surface_tension_model(SurfaceTensionModelInfo info) {
  for (const auto& m : surface_models_)
    if (m.name == info.name)
      throw std::logic_error("surface tension model '" + info.name + "' registered twice");
  surface_models_.push_back(std::move(info));
}

void Registry::add_material_kind(MaterialKind kind) {
  if (find_material_kind(kind.name))
    throw std::logic_error("material kind '" + kind.name + "' registered twice");
  kinds_.push_back(std::move(kind));
}

void Registry::add_scene_section(SceneSection section) {
  if (find_scene_section(section.key))
    throw std::logic_error("scene section '" + section.key + "' registered twice");
  sections_.push_back(std::move(section));
}

const SceneSection* Registry::find_scene_section(const std::string& key) const {
  for (const auto& s : sections_)
    if (s.key == key) return &s;
  return nullptr;
}

const SolverInfo* Registry::find_solver(const std::string& name) const {
  for (const auto& s : solvers_)
    if (s.name == name) return &s;
  return nullptr;
}

const MaterialKind* Registry::find_material_kind(const std::string& name) const {
  for (const auto& k : kinds_)
    if (k.name == name) return &k;
  return nullptr;
}

}  // namespace upf
