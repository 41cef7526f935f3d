// Writes the particles as a PLY point cloud (.ply) for Blender, MeshLab and other tools that do
// not read VTK files.
//
// Format: the Polygon File Format of G. Turk (1994), as described by Paul Bourke, "PLY - Polygon
// File Format", https://paulbourke.net/dataformats/ply/ : an ASCII header naming each element
// and its typed properties, then the data. We write `format binary_little_endian 1.0` and a
// single element, `vertex`, one per particle in the order of the arrays, its properties
// interleaved per vertex in the order the header lists them, with no padding:
//
//   float x, y, z                 position
//   uint8 red, green, blue        colour by particle type (type_palette.h)
//   uint32 id                     the stable particle id
//   uint8 type                    ParticleType value (0 liquid, 1 rigid, 2 granular, 3 frozen)
//   uint16 material               material index
//   float vx, vy, vz              velocity
//   float NAME                    each exported scalar field, in the order asked for
//   float NAME_x, NAME_y, NAME_z  each exported vector field
//
// The integer types carry their sizes in their names (uint8 rather than uchar): both spellings
// are in the format, and meshio's binary reader knows only some of the old ones (no "ushort").
// There is no face element: readers take a file with vertices only as a point cloud. Reals are
// written as float even when upf::Real is double: a picture needs no more, and float is what
// every PLY reader understands.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "framework/particles/particles.h"

namespace upf {

// Writes `particles` to `path` atomically (see write_file_atomically). `fields` names the fields
// to add after the fixed properties, as write_vtp does: names that match no field, that repeat
// one already written, or that are a fixed VTK array ("id", "type", "material", "velocity") are
// skipped, and so is a field whose PLY property name would repeat one already in the header
// (a scalar field "x", say). Characters that cannot stand in a header token (anything but
// printable ASCII other than space) become '_' in property names.
// Throws OutputError if the file cannot be written; the directory must exist.
void write_ply_points(const std::filesystem::path& path, const Particles& particles,
                      const std::vector<std::string>& fields);

// The bytes write_ply_points writes for `particles` and `fields`: the size estimate of a run.
std::size_t ply_points_bytes(const Particles& particles, const std::vector<std::string>& fields);

// The PLY property name for a field name: anything but printable ASCII other than space becomes
// '_' (a header is ASCII, its lines split at whitespace), and an empty name becomes "_".
std::string ply_property_name(std::string_view name);

}  // namespace upf
