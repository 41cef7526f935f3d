// Particle frames as OpenVDB point data grids ("VDB Points", Museth 2013 and OpenVDB's
// points::PointDataGrid): the format Houdini reads natively (Convert VDB Points SOP, attributes
// kept by name) and Blender and other OpenVDB tools open. One grid named "points" per file, with
// the attributes Houdini expects: P (positions), v (velocity), id (the stable particle id), type
// and material (integers), and every exported field by its own name (scalars as float, vectors as
// vec3f), density and pressure among them when the scene exports them.
//
// Positions in a point data grid are offsets from their voxel's centre. The voxel size is a power
// of two (about two particle spacings, some 8 particles per voxel, OpenVDB's advice), so the
// offsets and the positions they give back are the written floats exactly, uncompressed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/particles/particles.h"

namespace upf {

// How attributes are stored (openvdb::points codecs). Errors are those of the values read back.
enum class VdbPointsCodec {
  none,         // 32-bit floats: positions and attributes exact
  truncate,     // TruncateCodec: positions' offsets and float attributes as 16-bit halfs:
                // positions within voxel / 2^12, attributes within 2^-11 of their magnitude
  fixed_point,  // FixedPointCodec: positions as 16-bit fixed point in their voxel, within
                // voxel / 2^17; attributes as 32-bit floats (exact)
};

// The names of the codecs in a scene ("none", "truncate", "fixed_point").
const char* to_string(VdbPointsCodec codec);

// The voxel size for particle spacing `spacing`: the power of two nearest to 2 * spacing.
double vdb_points_voxel_size(double spacing);

// Writes `particles` (every one given) to `file` as a grid named "points". Throws OutputError
// when the file cannot be written.
void write_vdb_points(const std::filesystem::path& file, const Particles& particles,
                      const std::vector<std::string>& fields, double spacing, VdbPointsCodec codec);

}  // namespace upf
