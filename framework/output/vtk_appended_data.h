// Internal to the .vtp writers (write_vtp, write_mesh_vtp): one VTK XML PolyData file whose
// arrays sit in a raw appended binary block. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html (PolyData, appended
// data, header_type).
//
// Layout: the XML header lists every DataArray with format="appended" and an offset into the
// <AppendedData encoding="raw"> block, which starts after a '_' and holds, per array, a UInt64
// byte count followed by the array's bytes in the file's byte order. Compressed
// (compressor="vtkZLibDataCompressor"), an array is cut into blocks of kBlockBytes and its
// header is UInt64 [block count, block size, size of the last block, compressed size of each
// block], followed by the blocks, each a zlib stream (RFC 1950) of its block's bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace upf::vtk_xml {

using Header = std::uint64_t;  // header_type="UInt64": no 4 GiB limit per array.

// How the appended arrays are stored: as they are in memory, or zlib-compressed, which ParaView,
// VisIt and VTK's readers read as they do the files VTK itself writes compressed.
enum class Compression { none, zlib };

// VTK's own writer's block size: an array is compressed in independent blocks of this size.
inline constexpr std::size_t kBlockBytes = 32768;

// One DataArray, written straight from memory: `data` must outlive the write and hold `bytes`
// bytes laid out as `type` (a VTK type name such as "Float64") with `components` per tuple.
struct Array {
  std::string name;
  const char* type;
  int components;
  const void* data;
  std::size_t bytes;
};

template <class T>
Array make_array(std::string name, const char* type, int components, const std::vector<T>& v) {
  return {std::move(name), type, components, v.data(), v.size() * sizeof(T)};
}

// A child element of the <Piece> ("PointData", "CellData", "Points", "Verts", "Polys") and the
// arrays it holds, in file order.
struct Section {
  const char* tag;
  std::vector<Array> arrays;
};

// The sizes declared on the <Piece>; lines and strips are never written.
struct PieceCounts {
  std::size_t points = 0;
  std::size_t verts = 0;
  std::size_t polys = 0;
};

// Writes a PolyData file with one <Piece> holding `sections` to `path` atomically (see
// write_file_atomically). Throws OutputError if the file cannot be written.
void write_polydata(const std::filesystem::path& path, const PieceCounts& counts,
                    const std::vector<Section>& sections,
                    Compression compression = Compression::none);

}  // namespace upf::vtk_xml
