// Reads the VTK XML PolyData files upf writes (framework/output/vtp_writer.h, mesh_vtp_writer.h)
// back into memory, for pictures and tools. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html (PolyData, raw
// appended data, header_type).
//
// It reads what upf writes: one <Piece>, little-endian, UInt64 block headers, appended data raw
// or zlib-compressed, polygons that are all triangles. Any other layout is reported as unsupported,
// naming the file.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace upf::render {

// One DataArray with its values widened to double, tuple after tuple.
struct VtpArray {
  std::string name;
  int components = 1;
  std::vector<double> values;

  std::size_t tuples() const { return values.size() / std::size_t(components); }
  // The value of a scalar array, or the length of a vector one, for tuple `i`.
  double magnitude(std::size_t i) const;
};

struct PolyData {
  std::vector<Eigen::Vector3f> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<VtpArray> point_data;
  std::vector<VtpArray> cell_data;

  const VtpArray* point_array(std::string_view name) const;
  const VtpArray* cell_array(std::string_view name) const;
};

// A .pvtp (a split run's frame as pieces per rank) reads as its pieces' points joined, in order.
// Throws InputError naming `path` when it cannot be read or is not a file upf could have written.
PolyData read_vtp(const std::filesystem::path& path);

}  // namespace upf::render
