// Writes one triangle mesh (a MeshPiece, see mesh_vtp_writer.h) as PLY or OBJ, the two formats
// renderers (Blender, Houdini, MeshLab) read without a plug-in.
//
// PLY: binary little endian, "vertex" elements with float x, y, z and "face" elements with a
// list (uchar count, int indices) vertex_indices; format described by Greg Turk, "The PLY
// Polygon File Format" (http://paulbourke.net/dataformats/ply/). OBJ: text, "v x y z" lines then
// "f i j k" lines with 1-based indices (Wavefront OBJ, http://paulbourke.net/dataformats/obj/).
// Both keep the triangles' winding (counter-clockwise seen from the side the normal points to).
#pragma once

#include <filesystem>

#include "framework/output/mesh_vtp_writer.h"

namespace upf {

// Each writes `path` atomically (see write_file_atomically); the directory must exist. Throws
// std::invalid_argument, before touching the file, for a triangle index out of range or more
// vertices than a 32-bit signed index holds; OutputError if the file cannot be written. An empty
// mesh gives a valid file with no vertices and no faces.
void write_mesh_ply(const std::filesystem::path& path, const MeshPiece& mesh);
void write_mesh_obj(const std::filesystem::path& path, const MeshPiece& mesh);

}  // namespace upf
