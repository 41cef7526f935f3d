#include "framework/materials/material.h"

namespace upf {

MaterialId MaterialTable::add(Material m) {
  materials_.push_back(std::move(m));
  return MaterialId(materials_.size() - 1);
}

std::optional<MaterialId> MaterialTable::find(const std::string& name) const {
  for (std::size_t i = 0; i < materials_.size(); ++i)
    if (materials_[i].name == name) return MaterialId(i);
  return std::nullopt;
}

}  // namespace upf
