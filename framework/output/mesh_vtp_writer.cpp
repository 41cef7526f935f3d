// VTK XML PolyData writer for triangle meshes. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html; the appended-data
// layout is in vtk_appended_data.h.
//
// Polys are stored as two arrays: "connectivity", the point indices of all triangles one after
// the other, and "offsets", the end of each cell in connectivity (3, 6, 9, ...).
#include "framework/output/mesh_vtp_writer.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "framework/output/vtk_appended_data.h"

namespace upf {

namespace {

using vtk_xml::make_array;

// Checks everything that could make the file inconsistent, so a bad call writes nothing.
void check_input(const std::vector<MeshPiece>& pieces,
                 const std::vector<std::pair<std::string, std::vector<double>>>& piece_fields) {
  if (pieces.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::invalid_argument("write_mesh_vtp: too many pieces for the Int32 'body' array");
  }
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const MeshPiece& piece = pieces[i];
    for (std::size_t t = 0; t < piece.triangles.size(); ++t) {
      for (const std::uint32_t v : piece.triangles[t]) {
        if (v >= piece.vertices.size()) {
          throw std::invalid_argument(
              "write_mesh_vtp: triangle " + std::to_string(t) + " of piece " + std::to_string(i) +
              " ('" + piece.name + "') uses vertex " + std::to_string(v) + ", but the piece has " +
              std::to_string(piece.vertices.size()) + " vertices");
        }
      }
    }
  }
  // VTK keeps one array per name: a second "body" or a repeat would hide or be hidden.
  std::set<std::string> names = {"body"};
  for (const auto& [name, values] : piece_fields) {
    if (!names.insert(name).second) {
      throw std::invalid_argument("write_mesh_vtp: cell field '" + name +
                                  "' is reserved or given twice");
    }
    if (values.size() != pieces.size()) {
      throw std::invalid_argument("write_mesh_vtp: field '" + name + "' has " +
                                  std::to_string(values.size()) + " values for " +
                                  std::to_string(pieces.size()) + " pieces");
    }
  }
}

}  // namespace

void write_mesh_vtp(const std::filesystem::path& path, const std::vector<MeshPiece>& pieces,
                    const std::vector<std::pair<std::string, std::vector<double>>>& piece_fields,
                    vtk_xml::Compression compression) {
  check_input(pieces, piece_fields);

  std::size_t point_count = 0;
  std::size_t triangle_count = 0;
  for (const MeshPiece& piece : pieces) {
    point_count += piece.vertices.size();
    triangle_count += piece.triangles.size();
  }

  // Copied into flat arrays: the file needs one contiguous array per quantity across pieces.
  std::vector<double> points;
  points.reserve(3 * point_count);
  std::vector<std::int64_t> connectivity;
  connectivity.reserve(3 * triangle_count);
  std::vector<std::int64_t> offsets;
  offsets.reserve(triangle_count);
  std::vector<std::int32_t> body;
  body.reserve(triangle_count);
  std::vector<std::vector<double>> cell_values(piece_fields.size());
  for (auto& values : cell_values) values.reserve(triangle_count);

  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const MeshPiece& piece = pieces[i];
    // This piece's vertices start after those of the pieces before it.
    const auto first = static_cast<std::int64_t>(points.size() / 3);
    for (const Eigen::Vector3d& x : piece.vertices) {
      points.insert(points.end(), {x.x(), x.y(), x.z()});
    }
    for (const auto& triangle : piece.triangles) {
      for (const std::uint32_t v : triangle) connectivity.push_back(first + v);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      body.push_back(static_cast<std::int32_t>(i));
      for (std::size_t f = 0; f < piece_fields.size(); ++f) {
        cell_values[f].push_back(piece_fields[f].second[i]);
      }
    }
  }

  std::vector<vtk_xml::Array> cell_data = {make_array("body", "Int32", 1, body)};
  for (std::size_t f = 0; f < piece_fields.size(); ++f) {
    cell_data.push_back(make_array(piece_fields[f].first, "Float64", 1, cell_values[f]));
  }
  vtk_xml::write_polydata(path, {.points = point_count, .verts = 0, .polys = triangle_count},
                          {{"CellData", std::move(cell_data)},
                           {"Points", {make_array("Points", "Float64", 3, points)}},
                           {"Polys",
                            {make_array("connectivity", "Int64", 1, connectivity),
                             make_array("offsets", "Int64", 1, offsets)}}},
                          compression);
}

}  // namespace upf
