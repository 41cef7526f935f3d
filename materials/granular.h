// The granular material kind: spherical grains moved by a DEM solver (solvers/dem). The
// parameters cover both contact models; each model reads the ones it needs (docs/granular.md).
#pragma once

#include "framework/materials/material.h"

namespace upf {

MaterialKind granular_material_kind();

}  // namespace upf
