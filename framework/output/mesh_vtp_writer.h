// Writes triangle meshes (the rigid bodies in their current poses) as a VTK XML PolyData file
// (.vtp) for ParaView and VisIt, to sit beside the particle frame of the same step in a .pvd.
//
// All meshes go into one <Piece>: their vertices one after the other as Points, their triangles
// as Polys, and a "body" cell array telling which mesh each triangle came from, so one file per
// frame serves any number of bodies. Binary data in a raw appended block with 64-bit size
// headers, as write_vtp does. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html (PolyData, Polys,
// CellData, appended data).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/mesh_piece.h"
#include "framework/output/vtk_appended_data.h"

namespace upf {

// Writes all `pieces` into one PolyData file at `path`, atomically (see write_file_atomically).
// Points are Float64; triangle indices become Int64 connectivity into the concatenated points.
// Cell data holds "body" (Int32: the index of the triangle's piece in `pieces`), then each field
// of `piece_fields` in order (name -> one value per piece, written per triangle as Float64, e.g.
// "speed"). An empty `pieces` gives a valid file with 0 points and 0 polys.
// Throws std::invalid_argument, before touching the file, for a triangle index out of range, a
// field whose size differs from pieces.size(), or a field named "body" or named twice; throws
// OutputError if the file cannot be written; the directory must exist. `compression` as for
// write_vtp.
void write_mesh_vtp(const std::filesystem::path& path, const std::vector<MeshPiece>& pieces,
                    const std::vector<std::pair<std::string, std::vector<double>>>& piece_fields,
                    vtk_xml::Compression compression = vtk_xml::Compression::none);

}  // namespace upf
