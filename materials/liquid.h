// The liquid material kind: rest density and the viscosities every fluid solver applies.
#pragma once

#include "framework/materials/material.h"

namespace upf {
MaterialKind liquid_material_kind();
}  // namespace upf
