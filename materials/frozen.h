// The frozen material kind: static boundaries (container walls) sampled as particles.
#pragma once

#include "framework/materials/material.h"

namespace upf {
MaterialKind frozen_material_kind();
}  // namespace upf
