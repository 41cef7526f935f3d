// The OpenVDB frame writers a program hands to its runs (RunOptions::vdb_writers): the liquid
// surface mesher ("surface", liquid_surface.h) and the VDB points writer ("vdb_points",
// vdb_points_writer.h), with the run's thread count and the scene's compression.
#pragma once

#include "framework/run/frame_writer.h"

namespace upf {

VdbFrameWriters vdb_frame_writers();

}  // namespace upf
